#!/usr/bin/env python3
"""CTest `installed_authoring`: a new technique from an empty folder with only the installed package.

Installs BUILD_DIR into WORK_DIR/prefix, then in the empty folder WORK_DIR/esm runs what docs/authoring.md
tells a researcher to run: `shadowfx new esm`, `render` (the frame must show shadows: pixels darker than
the same frame with the shadow test disabled), `check` before goldens exist (passes, goldens NOT_SUPPORTED),
`check --update` (writes them beside the effect), `check` (passes against them), a small `bench` and a
`render` of a scene with a mesh file (the runtime modules they open must come from the prefix), and a
reduced `stress` whose JSON holds the comparison with the uniform map. The tool must find its effect
library in the prefix, not in the source tree.

usage: InstalledAuthoring.py BUILD_DIR WORK_DIR
"""
import json
import os
import pathlib
import shutil
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "scripts"))
from png_pixels import read_png  # noqa: E402

SIZE = ["--width", "160", "--height", "120"]


def run(command, cwd, env, expect=0):
    result = subprocess.run(command, cwd=cwd, env=env, capture_output=True, text=True)
    if result.returncode != expect:
        sys.exit(f"{' '.join(command)}\nexited {result.returncode}, expected {expect}:\n"
                 f"{result.stdout}\n{result.stderr}")
    return result.stdout + result.stderr


def main():
    build_dir, work_dir = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve()
    shutil.rmtree(work_dir, ignore_errors=True)
    prefix, folder = work_dir / "prefix", work_dir / "esm"
    folder.mkdir(parents=True)
    run(["cmake", "--install", str(build_dir), "--prefix", str(prefix)], work_dir, os.environ)
    env = dict(os.environ, PATH=f"{prefix / 'bin'}{os.pathsep}{os.environ['PATH']}")
    shadowfx = "shadowfx"

    # The installed tool reads the installed library.
    library = prefix / "share" / "shadowfx" / "effects"
    help_text = run([shadowfx, "render", "--help"], folder, env)
    if f"in the effect library: {library}" not in help_text:
        sys.exit(f"render --help does not name the installed library {library}:\n{help_text}")

    run([shadowfx, "new", "esm"], folder, env)
    run([shadowfx, "new", "esm"], folder, env, expect=1)  # never overwrites
    assert (folder / "esm.fx").is_file()

    # Shadows: the frame is darker somewhere than the same frame with every receiver lit (Bias 1 moves every
    # receiver in front of the map). A blank or constant frame has no such pixels.
    run([shadowfx, "render", "esm.fx", "--scene", "dual-l", *SIZE, "--out", "shadowed.png"], folder, env)
    run([shadowfx, "render", "esm.fx", "--scene", "dual-l", *SIZE, "--set", "Bias=1", "--out", "lit.png"],
        folder, env)
    shadowed, lit = read_png(folder / "shadowed.png"), read_png(folder / "lit.png")
    darker = sum(1 for a, b in zip(sum(shadowed, []), sum(lit, [])) if sum(b[:3]) - sum(a[:3]) > 60)
    pixels = 160 * 120
    if darker < pixels // 200:  # the L's shadow covers about 1.5 % of the frame
        sys.exit(f"the new effect renders no shadow: {darker} of {pixels} pixels darker than unshadowed")

    # Goldens: NOT_SUPPORTED before they exist, written beside the effect by --update, then compared.
    check = [shadowfx, "check", "esm.fx", "--backend", "egl", "--out", "check-failures"]
    def golden_rows(output):
        return [line for line in output.splitlines() if "  golden  " in line]

    before = run(check, folder, env)  # exit 0: nothing FAILs
    if len(golden_rows(before)) != 2 or not all(
            row.startswith("NOT_SUPPORTED") and "no goldens yet" in row for row in golden_rows(before)):
        sys.exit(f"check before --update:\n{before}")
    run(check + ["--update"], folder, env)
    goldens = sorted((folder / "golden" / "esm" / "main").glob("*.png"))
    if [g.name for g in goldens] != ["dual-l.png", "teapot.png"]:
        sys.exit(f"check --update wrote {goldens}, expected dual-l.png and teapot.png beside the effect")
    after = run(check, folder, env)
    if len(golden_rows(after)) != 2 or not all(row.startswith(("PASS", "QUALITY_WARNING"))
                                               for row in golden_rows(after)):
        sys.exit(f"check against the goldens:\n{after}")

    # The runtime modules come from the prefix (lib/shadowfx beside bin/), not from the build tree: the
    # dynamic loader's record of what it loaded (LD_DEBUG=files) names their paths.
    modules = prefix / "lib" / "shadowfx"
    loaded_env = dict(env, LD_DEBUG="files")
    loaded = run([shadowfx, "bench", "--effects", "esm.fx", "--scenes", "boxes", "--map-sizes", "256", *SIZE,
                  "--frames", "1", "--warmup", "0", "--out", "bench"], folder, loaded_env)
    loaded += run([shadowfx, "render", "esm.fx", "--scene", "bunny", *SIZE, "--out", "bunny.png"], folder,
                  loaded_env)
    for module in ("libshadowfx_raycast.so", "libshadowfx_meshimport.so"):
        if f"file={modules / module}" not in loaded:
            opened = [line for line in loaded.splitlines() if "libshadowfx_" in line]
            sys.exit(f"{module} was not loaded from {modules}:\n" + "\n".join(opened))
    runs = json.loads((folder / "bench" / "results.json").read_text())["runs"]
    if not runs or runs[0]["error"]["misclassified_percent"] is None:
        sys.exit(f"bench wrote no scored run: {runs}")

    run([shadowfx, "stress", "esm.fx", "--reduced", "--out", "stress"], folder, env)
    stress = json.loads((folder / "stress" / "stress.json").read_text())
    compared = [r for r in stress["results"] if r["uniform_percent"] is not None]
    if not compared:
        sys.exit(f"stress.json holds no comparison with the uniform map:\n{json.dumps(stress, indent=1)}")
    print(f"installed_authoring: {darker} shadowed pixels, {len(goldens)} goldens, "
          f"{len(compared)} stress runs compared with the uniform map")


if __name__ == "__main__":
    main()
