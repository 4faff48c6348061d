#!/usr/bin/env python3
"""The libraries' dependency graph, as CMake sees it (`cmake --graphviz`), checked and drawn.

  layering.py check  BUILD_DIR   configures the project into BUILD_DIR with --graphviz and fails on a cycle,
                                 an edge that points up the layer list below, a library missing from that
                                 list, or a library reaching a dependency it must not link
  layering.py render OUT.svg     the same graph, reduced to our targets and their direct third-party
                                 dependencies, drawn by Graphviz's `dot` (docs/ARCHITECTURE.md shows it)
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

SOURCE_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Our targets, lowest first: an edge may only point to a target earlier in this list.
LAYERS = ["report", "fxcontract", "fx", "scene", "assets", "lightspace", "gl", "render", "reload", "measure",
          "runtime", "shadowfx"]
# The runtime modules (runtime/RuntimeModules.h): shared libraries their opener loads with dlopen on first
# use. The opener's edge to one is a build-order dependency (add_dependencies), not a link: reaching a
# module does not reach what the module links.
MODULES = ["shadowfx_meshimport", "shadowfx_raycast"]
# What a library must not reach, directly or through another (the issue's "runs effects without
# Embree or assimp"; light fits without GL; reports without GL).
FORBIDDEN = {
    # Results into files: readable, writable and testable without GL, the effect compiler or Embree.
    "report": ["fx", "scene", "gl", "render", "measure", "OpenGL::EGL", "glfw", "embree", "assimp::assimp"],
    "scene": ["fx", "assimp::assimp", "nlohmann_json::nlohmann_json", "embree", "OpenGL::EGL", "glfw"],
    "lightspace": ["gl", "OpenGL::EGL", "glfw", "assimp::assimp", "nlohmann_json::nlohmann_json", "embree"],
    "gl": ["assimp::assimp", "nlohmann_json::nlohmann_json", "embree"],
    "render": ["assets", "measure", "assimp::assimp", "nlohmann_json::nlohmann_json", "embree", "fx",
               "glslang::glslang", "spirv-cross-core", "spirv-cross-glsl"],
    # assimp and Embree only in the runtime modules that assets and measure open on use
    # (runtime/RuntimeModules.h): no program that links the libraries loads them at start-up.
    "assets": ["assimp::assimp", "embree"],
    "measure": ["assimp::assimp", "embree"],
    "runtime": ["assimp::assimp", "embree"],
    "shadowfx": ["assimp::assimp", "embree"],
    # The contract: what an application loading compiled effect files links, without the compiler.
    "fxcontract": ["glslang::glslang", "glslang::SPIRV", "spirv-cross-core", "spirv-cross-glsl"],
}


def configure(build_dir):
    """Runs CMake's configure step with --graphviz; returns {name: set(dependencies)} and edge styles."""
    os.makedirs(build_dir, exist_ok=True)
    dot = os.path.join(build_dir, "targets.dot")
    subprocess.run(["cmake", "-S", SOURCE_DIR, "-B", build_dir, "-DSHADOWFX_BUILD_TESTS=OFF",
                    "-DSHADOWFX_BUILD_BENCHMARKS=OFF", f"--graphviz={dot}"],
                   check=True, stdout=subprocess.DEVNULL)
    labels, edges = {}, []
    with open(dot) as f:
        for line in f:
            m = re.match(r'\s*"(node\d+)" \[ label = "([^"]+)"', line)
            if m:
                labels[m.group(1)] = m.group(2)
            m = re.match(r'\s*"(node\d+)" -> "(node\d+)"(?: \[ style = (\w+) \])?', line)
            if m:
                edges.append((m.group(1), m.group(2), m.group(3) or "solid"))
    graph, styles = {}, {}
    for a, b, style in edges:
        graph.setdefault(labels[a], set()).add(labels[b])
        styles[(labels[a], labels[b])] = style
    for label in labels.values():
        graph.setdefault(label, set())
    return graph, styles


def ours(graph):
    """Targets defined by this project: those in LAYERS, and any library under runtime/ it does not know."""
    known = set(LAYERS)
    unknown = []
    for name in graph:
        if name in known or "::" in name or "/" in name or name.startswith("-"):
            continue
        if os.path.isdir(os.path.join(SOURCE_DIR, "runtime", name)):
            unknown.append(name)
    return unknown


def reach(graph, start):
    """What `start` links, directly or through another target; a runtime module is reached, not entered."""
    seen, stack = set(), [start]
    while stack:
        node = stack.pop()
        if node in MODULES and node != start:
            continue
        for dep in graph.get(node, ()):
            if dep not in seen:
                seen.add(dep)
                stack.append(dep)
    return seen


def find_cycle(graph):
    state, path = {}, []

    def visit(node):
        state[node] = 1
        path.append(node)
        for dep in sorted(graph.get(node, ())):
            if state.get(dep) == 1:
                return path[path.index(dep):] + [dep]
            if dep not in state:
                cycle = visit(dep)
                if cycle:
                    return cycle
        state[node] = 2
        path.pop()
        return None

    for node in sorted(graph):
        if node not in state:
            cycle = visit(node)
            if cycle:
                return cycle
    return None


def check(build_dir):
    graph, _ = configure(build_dir)
    errors = []
    cycle = find_cycle(graph)
    if cycle:
        errors.append("cycle: " + " -> ".join(cycle))
    for name in ours(graph):
        errors.append(f"library '{name}' (runtime/{name}) is not in scripts/layering.py's LAYERS: place it")
    rank = {name: i for i, name in enumerate(LAYERS)}
    for name in LAYERS:
        for dep in sorted(graph.get(name, ())):
            if dep in rank and rank[dep] >= rank[name]:
                errors.append(f"upward edge: {name} -> {dep} ({dep} sits above {name} in LAYERS)")
    for name, banned in FORBIDDEN.items():
        reached = reach(graph, name)
        for dep in banned:
            if dep in reached:
                errors.append(f"{name} reaches {dep}, which it must not link")
    missing = [name for name in LAYERS + MODULES if name not in graph]
    if missing:
        errors.append("targets not found in the graph: " + ", ".join(missing))
    for error in errors:
        print("layering: " + error, file=sys.stderr)
    if not errors:
        print(f"layering: {len(LAYERS)} targets, no cycle, every edge points down")
    return 1 if errors else 0


def render(out):
    with tempfile.TemporaryDirectory() as build_dir:
        graph, styles = configure(build_dir)
    keep = [name for name in LAYERS + MODULES if name in graph]
    lines = ['digraph shadowfx {', '  rankdir=BT; node [shape=box, fontname="Helvetica", fontsize=11];',
             '  edge [color="#555555"];']
    for name in keep:
        shape = ("ellipse" if name == "shadowfx" else "box, style=dashed" if name == "runtime" else
                 "component" if name in MODULES else "box")
        lines.append(f'  "{name}" [shape={shape}];')
    third = set()
    for name in keep:
        for dep in sorted(graph[name]):
            # Leave out edges implied by a longer path: the picture shows the layering, not every link.
            if any(dep in reach(graph, other) for other in graph[name] if other in keep and other != dep):
                continue
            if dep in MODULES:
                lines.append(f'  "{name}" -> "{dep}" [style=dashed, label="opens", fontsize=9];')
            elif dep in keep:
                lines.append(f'  "{name}" -> "{dep}";')
            elif not dep.startswith(("/", "-", "$")) and dep not in ("Threads::Threads", "dl"):
                third.add(dep)
                style = "dotted" if styles.get((name, dep)) == "dotted" else "solid"
                lines.append(f'  "{name}" -> "{dep}" [style={style}, color="#999999"];')
    for dep in sorted(third):
        lines.append(f'  "{dep}" [shape=plaintext, fontcolor="#666666", fontsize=9];')
    lines.append("}")
    fmt = os.path.splitext(out)[1].lstrip(".") or "svg"  # svg, png, ...
    subprocess.run(["dot", f"-T{fmt}", "-o", out], input="\n".join(lines), text=True, check=True)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in ("check", "render"):
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    if sys.argv[1] == "render" and not shutil.which("dot"):
        sys.exit("layering: Graphviz's dot is missing (apt-get install graphviz)")
    sys.exit(check(sys.argv[2]) if sys.argv[1] == "check" else render(sys.argv[2]))
