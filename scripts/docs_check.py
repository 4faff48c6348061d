#!/usr/bin/env python3
"""Checks that the documentation's pointers resolve and that the effect library is documented.

  docs_check.py pointers SOURCE_DIR        every page, section and anchor that effects, headers, sources,
                                           --help texts, messages and docs cite exists
  docs_check.py effect-library SOURCE_DIR  every name effects/include/*.fxh exports is documented on its
                                           page docs/effect-library/STEM.md, and every documented name exists

Exit status 1 with one line per problem, 0 when everything resolves.
"""
import functools
import pathlib
import re
import sys

# [SECTION] Sections and anchors of a Markdown page


@functools.lru_cache(maxsize=None)
def headings(page):
    """The section titles of a Markdown page (backticks dropped) and their GitHub anchors."""
    titles, anchors = set(), set()
    in_code = False
    for line in page.read_text(encoding="utf-8").splitlines():
        if line.startswith("```"):
            in_code = not in_code
        if in_code:
            continue
        match = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
        if not match:
            continue
        title = match.group(1).replace("`", "")
        titles.add(title)
        anchor = re.sub(r"[^\w\- ]", "", title.lower()).replace(" ", "-")
        anchors.add(anchor)
    return titles, anchors


# [SECTION] Pointers
# The forms a pointer takes in this tree:
#   (docs/PAGE.md, "Section")   docs/PAGE.md   docs/PAGE.md#anchor   (README, "Section")
#   [text](relative/page.md#anchor) in Markdown
CITED_SOURCES = ["effects", "fx", "report", "runtime", "samples", "benchmarks", "tests", "scripts", "cmake", "fuzz"]
SOURCE_SUFFIXES = {".fx", ".fxh", ".h", ".cpp", ".cmake", ".txt", ".py", ".sh", ".json"}
PAGE_WITH_SECTION = re.compile(r'\b((?:docs/)[\w./-]+\.md)(?:#([\w-]+))?(?:,\s*\\?"([^"\\]+)\\?")?')
README_SECTION = re.compile(r'\bREADME(?:\.md)?(?:,|\'s)?\s+\\?"([^"\\]+)\\?"')
MARKDOWN_LINK = re.compile(r"\]\(([^)\s]+?\.md)(?:#([\w-]+))?\)")


def check_page(root, base, target, anchor, section, where, problems):
    page = (base / target).resolve() if not target.startswith("docs/") else (root / target)
    if not page.is_file():
        problems.append(f"{where}: {target}: no such page")
        return
    if anchor or section:
        titles, anchors = headings(page)
        if anchor and anchor not in anchors:
            problems.append(f"{where}: {target}#{anchor}: no such section")
        if section and section.replace("`", "") not in titles:
            problems.append(f'{where}: {target}, "{section}": no such section')


def check_pointers(root):
    problems = []
    readme_titles = headings(root / "README.md")[0]
    files = [p for d in CITED_SOURCES for p in (root / d).rglob("*")
             if p.is_file() and p.suffix in SOURCE_SUFFIXES and "golden" not in p.parts
             and p != pathlib.Path(__file__).resolve() and not p.is_relative_to(root / "tests" / "data")]
    files += [root / "README.md"] + list((root / "docs").rglob("*.md"))
    for path in sorted(files):
        lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
        # A pointer may wrap across comment lines: join them, keeping the line of each match's start.
        relative = path.relative_to(root)
        for number, line in enumerate(lines, 1):
            if "README" not in line and ".md" not in line:
                continue
            where = f"{relative}:{number}"
            joined = line + " " + " ".join(lines[number:number + 1])
            joined = re.sub(r'"\s*\\n"\s*"|\s*(//|#|\*)\s*', " ", joined)
            for match in PAGE_WITH_SECTION.finditer(joined):
                if match.start() >= len(line):
                    continue
                check_page(root, root, match.group(1), match.group(2), match.group(3), where, problems)
            for match in README_SECTION.finditer(joined):
                if match.start() >= len(line):
                    continue
                if match.group(1).replace("`", "") not in readme_titles:
                    problems.append(f'{where}: README, "{match.group(1)}": no such section')
    pages = [root / "README.md"] + sorted((root / "docs").rglob("*.md"))
    for page in pages:
        in_code = False
        for number, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1):
            if line.startswith("```"):
                in_code = not in_code
            where = f"{page.relative_to(root)}:{number}"
            for match in MARKDOWN_LINK.finditer(line):
                target = match.group(1)
                if re.match(r"\w+://", target):
                    continue
                check_page(root, page.parent, target, match.group(2), None, where, problems)
    return problems


# [SECTION] Effect library


def exported_names(header):
    """Names a header gives the effects that include it: macros (not the include guard), structs,
    functions and global parameters, textures and samplers declared at the top level."""
    text = header.read_text(encoding="utf-8")
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    text = re.sub(r"\\\n", " ", text)  # macro bodies are one line
    names, depth = set(), 0
    declaration = re.compile(r"(?:static\s+)?(?:const\s+)?(?:uniform\s+)?[A-Za-z_]\w*\s+([A-Za-z_]\w*)\s*"
                             r"(?:[(:<=;\[]|$)")
    for line in text.splitlines():
        if depth == 0:
            if match := re.match(r"#define\s+(\w+)", line):
                if not re.fullmatch(r"SHADOWFX_\w+_FXH", match.group(1)):
                    names.add(match.group(1))
            elif match := re.match(r"struct\s+(\w+)", line):
                names.add(match.group(1))
            elif not line.startswith("#") and (match := declaration.match(line)):
                names.add(match.group(1))
        if not line.startswith("#"):
            depth += line.count("{") - line.count("}")
    return names


def documented_names(page):
    """The names a reference page documents: each is written in bold code, **`Name`**."""
    return set(re.findall(r"\*\*`([A-Za-z_]\w*)`\*\*", page.read_text(encoding="utf-8")))


def check_effect_library(root):
    problems = []
    headers = sorted((root / "effects" / "include").glob("*.fxh"))
    pages = root / "docs" / "effect-library"
    for header in headers:
        page = pages / (header.stem + ".md")
        if not page.is_file():
            problems.append(f"{header.relative_to(root)}: no reference page {page.relative_to(root)}")
            continue
        exported, documented = exported_names(header), documented_names(page)
        for name in sorted(exported - documented):
            problems.append(f"{page.relative_to(root)}: {name} ({header.name}) is not documented")
        for name in sorted(documented - exported):
            problems.append(f"{page.relative_to(root)}: {name} is documented but {header.name} has no such name")
    for page in sorted(pages.glob("*.md")):
        if page.name != "README.md" and not (root / "effects" / "include" / (page.stem + ".fxh")).is_file():
            problems.append(f"{page.relative_to(root)}: no header effects/include/{page.stem}.fxh")
    return problems


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("pointers", "effect-library"):
        print(__doc__, file=sys.stderr)
        return 2
    root = pathlib.Path(sys.argv[2]).resolve()
    problems = check_pointers(root) if sys.argv[1] == "pointers" else check_effect_library(root)
    for problem in problems:
        print(problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
