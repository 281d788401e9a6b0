#!/usr/bin/env python3
"""Keeps the code shown in docs and header usage comments equal to compiled snippet files.

Every code example in docs/*.md and README.md that follows a marker, and the usage example
at the top of every public header (runtime/*/include/prism/**/*.hpp,
foundation/*/include/prism/**/*.hpp, shaderc_tool/include/prism/shaderc/*.hpp), is a copy of a
file under examples/snippets/ that tests/snippets builds and runs. This script checks that the copies are exact.

Markers:
  Markdown:  <!-- snippet: examples/snippets/NAME.cpp -->   then a ```cpp fenced block
  Header:    a `//` comment line containing `snippet: examples/snippets/NAME.cpp`, then the
             indented comment block (`//     code`, blank `//` lines allowed)
  Snippet:   the shown text is every region between `// [snippet]` and `// [/snippet]`
             lines (`# [snippet]` and `# [/snippet]` in CMake files), each region dedented
             by its smallest indentation, regions joined in order; the rest of the file is
             the harness (main, inputs, checks).

Every public header must have a snippet marker, and every snippet file must be shown
somewhere. Errors are GCC style (`path:line: error: ...`); exit status 1 on any error.

  check_snippets.py [ROOT]          check the tree at ROOT (default: the repository)
  check_snippets.py --update        rewrite every marked block from its snippet file
  check_snippets.py --self-test     copy the tree, edit one header example, and show that
                                    the check then fails naming that header
"""
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

SNIPPET_DIR = "examples/snippets"
HEADER_GLOBS = ["runtime/*/include/prism/**/*.hpp", "foundation/*/include/prism/**/*.hpp",
                "shaderc_tool/include/prism/shaderc/*.hpp"]
DOC_GLOBS = ["docs/*.md", "README.md"]
FULLY_CHECKED_DOCS = ["docs/runtime.md"]  # here every ```cpp / ```cmake block needs a marker
MD_MARKER = re.compile(r"^<!-- snippet: (\S+) -->\s*$")
HEADER_MARKER = re.compile(r"^//.*\bsnippet: (examples/snippets/[\w./-]+\.cpp)")
CODE_PREFIX = "//     "


def dedent(lines):
    indents = [len(l) - len(l.lstrip(" ")) for l in lines if l.strip()]
    cut = min(indents) if indents else 0
    return [l[cut:] if l.strip() else "" for l in lines]


def shown_text(path):
    """The text a snippet file shows: its [snippet] regions, dedented and joined."""
    shown, region, errors = [], None, []
    comment = "#" if path.suffix == ".txt" or path.suffix == ".cmake" else "//"
    for number, line in enumerate(path.read_text().splitlines(), 1):
        marker = line.strip().replace(comment + " [", "// [", 1)
        if marker == "// [snippet]" or marker.startswith("// [snippet] "):
            if region is not None:
                errors.append(f"{path}:{number}: error: `// [snippet]` inside an open region")
            region = []
        elif marker == "// [/snippet]" or marker.startswith("// [/snippet] "):
            if region is None:
                errors.append(f"{path}:{number}: error: `// [/snippet]` without `// [snippet]`")
            else:
                shown.extend(dedent(region))
                region = None
        elif region is not None:
            region.append(line.rstrip())
    if region is not None:
        errors.append(f"{path}: error: a `// [snippet]` region is not closed")
    if not shown and not errors:
        errors.append(f"{path}: error: no `// [snippet]` region: nothing is shown from this file")
    return shown, errors


def markdown_blocks(path):
    """(first line of the block, snippet path, block lines or None) for each marker."""
    lines = path.read_text().splitlines()
    found = []
    for i, line in enumerate(lines):
        m = MD_MARKER.match(line)
        if not m:
            continue
        j = i + 1
        while j < len(lines) and not lines[j].strip():
            j += 1
        if j >= len(lines) or not lines[j].startswith("```"):
            found.append((i + 1, m.group(1), None, None))  # reported at the marker
            continue
        block = []
        j += 1
        start = j + 1
        while j < len(lines) and not lines[j].startswith("```"):
            block.append(lines[j].rstrip())
            j += 1
        found.append((start, m.group(1), block, j))
    return found


def header_blocks(path):
    """(first line of the block, snippet path, block lines) for each marker in a header."""
    lines = path.read_text().splitlines()
    found = []
    for i, line in enumerate(lines):
        m = HEADER_MARKER.match(line)
        if not m:
            continue
        j = i + 1
        while j < len(lines) and lines[j].rstrip() == "//":
            j += 1
        start = j + 1
        block = []
        while j < len(lines) and (lines[j].startswith(CODE_PREFIX) or lines[j].rstrip() == "//"):
            block.append(lines[j][len(CODE_PREFIX):].rstrip() if lines[j].startswith(CODE_PREFIX) else "")
            j += 1
        while block and not block[-1]:
            block.pop()
        found.append((start, m.group(1), block, start - 1 + len(block)))
    return found


def first_difference(expected, actual):
    for k in range(max(len(expected), len(actual))):
        e = expected[k] if k < len(expected) else "<end>"
        a = actual[k] if k < len(actual) else "<end>"
        if e != a:
            return k, e, a
    return None


def check(root):
    root = pathlib.Path(root).resolve()
    errors, used = [], set()
    cache = {}

    def compare(where, line, rel, block, kind):
        used.add(rel)
        snippet = root / rel
        if not snippet.is_file():
            errors.append(f"{where}:{line}: error: snippet file {rel} does not exist")
            return
        if rel not in cache:
            cache[rel] = shown_text(snippet)
            errors.extend(cache[rel][1])
        expected = cache[rel][0]
        if block is None:
            errors.append(f"{where}:{line}: error: the snippet marker for {rel} is not followed by a ``` block")
            return
        diff = first_difference(expected, block)
        if diff:
            k, e, a = diff
            errors.append(f"{where}:{line + k}: error: "
                          f"this {kind} example differs from {rel} at its line {k + 1}:\n"
                          f"    file:  {e}\n    shown: {a}\n"
                          f"  edit {rel} (tests/snippets compiles and runs it), then copy it here with "
                          f"`python3 scripts/check_snippets.py --update`")

    headers = sorted({p for g in HEADER_GLOBS for p in root.glob(g)})
    for header in headers:
        rel_header = header.relative_to(root)
        blocks = header_blocks(header)
        if not blocks:
            errors.append(f"{rel_header}:1: error: a public header needs a usage example marked "
                          f"`// Usage (snippet: {SNIPPET_DIR}/NAME.cpp):`")
        for line, rel, block, _ in blocks:
            compare(rel_header, line, rel, block, "header")
    for doc in sorted({p for g in DOC_GLOBS for p in root.glob(g)}):
        marked = set()
        for line, rel, block, _ in markdown_blocks(doc):
            compare(doc.relative_to(root), line, rel, block, "doc")
            marked.add(line - 1)
        if str(doc.relative_to(root)) in FULLY_CHECKED_DOCS:
            for number, text in enumerate(doc.read_text().splitlines(), 1):
                if re.match(r"^```(cpp|c\+\+|cmake)\s*$", text) and number not in marked:
                    errors.append(f"{doc.relative_to(root)}:{number}: error: a code block without a "
                                  f"`<!-- snippet: {SNIPPET_DIR}/NAME.cpp -->` marker is not compiled by any test")
    for snippet in sorted((root / SNIPPET_DIR).glob("*.cpp")):
        rel = str(snippet.relative_to(root))
        if rel not in used:
            errors.append(f"{rel}:1: error: shown by no doc or header; mark where it belongs or delete it")
    for e in errors:
        print(e)
    count = len(headers)
    print(f"check_snippets: {len(used)} snippet files, {count} public headers: "
          f"{'OK' if not errors else str(len(errors)) + ' error(s)'}")
    return 1 if errors else 0


def update(root):
    """Rewrites every marked doc block and header example from its snippet file."""
    root = pathlib.Path(root).resolve()
    files = sorted({p for g in HEADER_GLOBS + DOC_GLOBS for p in root.glob(g)})
    for path in files:
        header = path.suffix == ".hpp"
        blocks = header_blocks(path) if header else markdown_blocks(path)
        lines = path.read_text().splitlines(keepends=True)
        for start, rel, block, end in reversed(blocks):
            if block is None or not (root / rel).is_file():
                continue
            shown, _ = shown_text(root / rel)
            if header:
                new = [(CODE_PREFIX + l if l else "//") + "\n" for l in shown]
            else:
                new = [l + "\n" for l in shown]
            lines[start - 1:end] = new
        text = "".join(lines)
        if text != path.read_text():
            path.write_text(text)
            print(f"check_snippets: updated {path.relative_to(root)}")
    return 0


def self_test(root):
    """Copy the tree, rename a function in one header example, expect the check to fail."""
    root = pathlib.Path(root).resolve()
    with tempfile.TemporaryDirectory() as tmp:
        copy = pathlib.Path(tmp)
        for pattern in HEADER_GLOBS + DOC_GLOBS + [SNIPPET_DIR + "/*.cpp", "examples/*/CMakeLists.txt"]:
            for p in root.glob(pattern):
                target = copy / p.relative_to(root)
                target.parent.mkdir(parents=True, exist_ok=True)
                shutil.copy2(p, target)
        header = copy / "runtime/gl/include/prism/gl/framebuffer.hpp"
        text = header.read_text()
        mutated = text.replace("fb.readImage8()", "fb.readImage()", 1)
        if mutated == text:
            print("self-test: error: framebuffer.hpp's example no longer calls fb.readImage8(); update the self-test")
            return 1
        header.write_text(mutated)
        run = subprocess.run([sys.executable, __file__, str(copy)], capture_output=True, text=True)
        print(run.stdout, end="")
        wanted = "runtime/gl/include/prism/gl/framebuffer.hpp:"
        if run.returncode == 1 and wanted in run.stdout and "shown: " in run.stdout:
            print("self-test: OK: the drifted header example was rejected")
            return 0
        print("self-test: error: the check accepted a header example that differs from its snippet file")
        return 1


if __name__ == "__main__":
    args = sys.argv[1:]
    repo = pathlib.Path(__file__).resolve().parent.parent
    if args == ["--self-test"]:
        sys.exit(self_test(repo))
    if args == ["--update"]:
        sys.exit(update(repo))
    if len(args) > 1 or (args and args[0].startswith("-")):
        print("usage: check_snippets.py [ROOT] | --update | --self-test", file=sys.stderr)
        sys.exit(2)
    sys.exit(check(args[0] if args else repo))
