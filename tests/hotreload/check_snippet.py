#!/usr/bin/env python3
"""Checks that the hot-reload usage example is the same code in the three places that
show it: the test that runs it (between `// [snippet: hot reload]` and `// [end snippet]`),
the usage comment of shader_watcher.hpp (its first block of `//     ` lines) and
docs/hot-reload.md (the ```cpp block after `<!-- snippet: hot reload -->`).
usage: check_snippet.py SOURCE_DIR   (exit 1 and a diff when they differ)"""
import difflib
import pathlib
import sys


def from_test(text):
    block = text.split("// [snippet: hot reload]\n", 1)[1].split("// [end snippet]", 1)[0]
    return [line[4:] if line.startswith("    ") else line for line in block.rstrip().splitlines()]


def from_header(text):
    lines, started = [], False
    for line in text.splitlines():
        if line.startswith("//     "):
            started = True
            lines.append(line[7:])
        elif started:
            break
    return lines


def from_doc(text):
    block = text.split("<!-- snippet: hot reload -->", 1)[1].split("```cpp\n", 1)[1].split("```", 1)[0]
    return block.rstrip().splitlines()


def main():
    root = pathlib.Path(sys.argv[1])
    reference = from_test((root / "tests/hotreload/test_gl_shader_watcher.cpp").read_text())
    others = {
        "runtime/render/include/prism/render/shader_watcher.hpp": from_header(
            (root / "runtime/render/include/prism/render/shader_watcher.hpp").read_text()),
        "docs/hot-reload.md": from_doc((root / "docs/hot-reload.md").read_text()),
    }
    ok = bool(reference)
    for name, lines in others.items():
        if lines != reference:
            ok = False
            print(f"{name}: the hot-reload snippet differs from the one the test runs:")
            print("\n".join(difflib.unified_diff(reference, lines, "test", name, lineterm="")))
    print("hot-reload snippet: " + ("identical in test, header and docs" if ok else "MISMATCH"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
