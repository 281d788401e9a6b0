#!/usr/bin/env python3
"""Times one compile of a build tree at several optimisation levels (docs/ci.md).

    scripts/time-batch-compile.py BUILD_DIR OBJECT_SUBSTRING FLAG [FLAG...]
    scripts/time-batch-compile.py build prism_shaderc_tests.dir/Unity/unity_1_ -O3 -O1

Takes the first command of BUILD_DIR/compile_commands.json whose text contains
OBJECT_SUBSTRING, drops its precompiled header (built for one level only; GCC's -include or
Clang's -Xclang -include-pch), adds each FLAG last, writes to a scratch object, and prints
the wall time and the CPU time (user + system: the figure to compare on a shared machine)
of each compile.
"""
import json
import resource
import shlex
import subprocess
import sys
import tempfile
import time
from pathlib import Path


def main() -> int:
    if len(sys.argv) < 4:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    build, needle, flags = Path(sys.argv[1]), sys.argv[2], sys.argv[3:]
    entries = json.loads((build / "compile_commands.json").read_text())
    entry = next((e for e in entries if needle in e["command"]), None)
    if entry is None:
        print(f"{build / 'compile_commands.json'}: no command contains '{needle}'", file=sys.stderr)
        return 1
    args = shlex.split(entry["command"])
    if "-include-pch" in args:  # Clang: -Xclang -include-pch -Xclang <pch> -Xclang -include -Xclang <hxx>
        at = args.index("-include-pch") - 1
        del args[at:at + 8]
    elif "-include" in args:
        at = args.index("-include")
        del args[at:at + 2]
    args = [a for a in args if a not in ("-Winvalid-pch",)]
    out = args.index("-o")
    with tempfile.TemporaryDirectory() as scratch:
        args[out + 1] = str(Path(scratch) / "batch.o")
        for flag in flags:
            start, cpu_before = time.monotonic(), resource.getrusage(resource.RUSAGE_CHILDREN)
            result = subprocess.run(args[:out] + [flag] + args[out:], cwd=entry["directory"], capture_output=True)
            cpu_after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpu = cpu_after.ru_utime - cpu_before.ru_utime + cpu_after.ru_stime - cpu_before.ru_stime
            status = "" if result.returncode == 0 else f" (failed: {result.stderr.decode()[-200:]})"
            print(f"{flag}: {time.monotonic() - start:.1f} s, {cpu:.1f} s CPU{status}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
