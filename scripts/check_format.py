#!/usr/bin/env python3
"""Checks that Prism's C and C++ sources are formatted as .clang-format says.

Runs `clang-format --dry-run -Werror` (Debian 12's clang-format 14; other majors format
differently, so another major is refused rather than trusted) over the source folders,
leaving out recorded outputs that are compared byte for byte (tests/**/baseResults), test
fixtures and fuzz corpora. Lines over the column limit count too, comments and strings
included (clang-format does not reflow those here). Prints clang-format's own `path:line:col: error:` lines and a
one-line summary; exits 1 when a file needs formatting, 2 on a usage or tool problem.

    python3 scripts/check_format.py            # check the tree (CTest `format`)
    python3 scripts/check_format.py --fix      # rewrite the files in place
    python3 scripts/check_format.py --root tests/format/fixtures/unformatted   # one folder
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

SOURCE_FOLDERS = ["apps", "bench", "examples", "runtime", "shaderc_tool", "tests"]
EXTENSIONS = (".c", ".h", ".cpp", ".hpp")
LEFT_OUT_FOLDERS = {"baseResults", "fixtures", "corpus"}
REQUIRED_MAJOR = 14
BATCH = 64


def source_files(repo, roots):
    files = []
    for root in roots:
        for folder, subfolders, names in os.walk(os.path.join(repo, root)):
            subfolders[:] = sorted(d for d in subfolders if d not in LEFT_OUT_FOLDERS)
            files += [os.path.join(folder, n) for n in sorted(names) if n.endswith(EXTENSIONS)]
    return files


def clang_format_binary():
    exe = shutil.which("clang-format-%d" % REQUIRED_MAJOR) or shutil.which("clang-format")
    if exe is None:
        sys.exit("check_format: error: clang-format not found; run scripts/setup.sh (package clang-format-14)")
    version = subprocess.run([exe, "--version"], capture_output=True, text=True).stdout
    major = re.search(r"version (\d+)", version)
    if not major or int(major.group(1)) != REQUIRED_MAJOR:
        sys.exit("check_format: error: %s is '%s'; the format is defined by clang-format %d"
                 % (exe, version.strip(), REQUIRED_MAJOR))
    return exe


def column_limit(repo):
    folder = repo
    while not os.path.exists(os.path.join(folder, ".clang-format")) and os.path.dirname(folder) != folder:
        folder = os.path.dirname(folder)
    with open(os.path.join(folder, ".clang-format")) as style:
        found = re.search(r"^ColumnLimit:\s*(\d+)", style.read(), re.MULTILINE)
    return int(found.group(1)) if found else 80


def long_lines(files, limit):
    """clang-format leaves comments and string literals as they are (ReflowComments: false),
    so lines over the column limit are counted here."""
    failing = set()
    for path in files:
        with open(path, encoding="utf-8", errors="replace") as source:
            for number, line in enumerate(source, 1):
                width = len(line.rstrip("\n"))
                if width > limit:
                    print("%s:%d:%d: error: line is %d columns, over the limit of %d; break it"
                          % (path, number, limit + 1, width, limit))
                    failing.add(path)
    return failing


def run(exe, files, fix, repo):
    args = [exe, "--style=file"] + (["-i"] if fix else ["--dry-run", "-Werror"])
    failing = set()
    for start in range(0, len(files), BATCH):
        batch = files[start:start + BATCH]
        result = subprocess.run(args + batch, capture_output=True, text=True, cwd=repo)
        for line in result.stderr.splitlines():
            path = line.split(":", 1)[0]
            if ": error:" in line and path not in failing:  # the first place in each file is enough
                print(line)
                failing.add(path)
    return failing


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repo", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    parser.add_argument("--root", action="append", help="folder below --repo to check (default: the source folders)")
    parser.add_argument("--fix", action="store_true", help="rewrite the files instead of checking them")
    options = parser.parse_args()
    options.repo = os.path.abspath(options.repo)
    files = source_files(options.repo, options.root or SOURCE_FOLDERS)
    if not files:
        sys.exit("check_format: error: no C or C++ sources under %s" % (options.root or SOURCE_FOLDERS))
    failing = run(clang_format_binary(), files, options.fix, options.repo)
    failing |= long_lines(files, column_limit(options.repo))
    if failing:
        print("check_format: %d of %d files need formatting; run: python3 scripts/check_format.py --fix"
              % (len(failing), len(files)))
        return 1
    print("check_format: %d files %s" % (len(files), "formatted" if options.fix else "are formatted"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
