#!/usr/bin/env python3
"""Lists C++ functions longer than a limit, so long functions cannot creep back.

universal-ctags (Debian package universal-ctags) finds every function definition and its
first and last line; a function's length is last - first + 1, its signature and braces
included. Lambdas count as functions of their own ("lambda in NAME") and also count in the
lines of the function around them. Offenders are printed GCC style and the exit status is 1:

    runtime/x/src/y.cpp:12: error: function 'prism::x::draw' is 90 lines (limit 80)

    check_function_length.py [--max N] PATH...
        PATH     files or folders to scan (folders recursively, C++ files only)
        --max    the longest function allowed, in lines (default 80)

The CTest architecture.function_length runs it over every folder with C++ but bench/
(benchmarks keep their measured loops whole); architecture.rejects_a_long_function runs it
over a generated fixture it must reject.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys


def ctags_functions(paths):
    """Yields (path, first line, last line, name) of every function definition ctags finds."""
    ctags = shutil.which("ctags")
    if not ctags:
        sys.exit("check_function_length.py: error: ctags not found; install universal-ctags (scripts/setup.sh)")
    command = [ctags, "--output-format=json", "--fields=+ne", "--kinds-C++=f", "--languages=C++", "-R", "-f", "-"]
    result = subprocess.run(command + list(paths), capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("check_function_length.py: error: ctags failed: " + result.stderr.strip())
    for line in result.stdout.splitlines():
        tag = json.loads(line)
        if tag.get("_type") == "tag" and "end" in tag:
            yield tag["path"], tag["line"], tag["end"], display_name(tag)


def display_name(tag):
    """The qualified name without anonymous namespaces; ctags names a lambda __anon..."""
    scope = "::".join(part for part in tag.get("scope", "").split("::") if part and not part.startswith("__anon"))
    if tag["name"].startswith("__anon"):
        return "lambda in " + (scope or "file scope")
    return scope + "::" + tag["name"] if scope else tag["name"]


def main():
    parser = argparse.ArgumentParser(description="Lists C++ functions over a line limit (needs universal-ctags).")
    parser.add_argument("paths", nargs="+", help="files or folders to scan")
    parser.add_argument("--max", type=int, default=80, help="the longest function allowed, in lines")
    args = parser.parse_args()
    for path in args.paths:
        if not os.path.exists(path):
            sys.exit(f"check_function_length.py: error: {path}: no such file or folder")
    offenders = []
    for path, first, last, name in ctags_functions(args.paths):
        lines = last - first + 1
        if lines > args.max:
            offenders.append((path, first, name, lines))
    for path, first, name, lines in sorted(offenders):
        print(f"{path}:{first}: error: function '{name}' is {lines} lines (limit {args.max})")
    if offenders:
        print(f"{len(offenders)} function(s) over {args.max} lines; split them into named steps", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
