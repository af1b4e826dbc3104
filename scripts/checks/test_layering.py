#!/usr/bin/env python3
"""The layering check against made-up source trees: it passes a clean one and fails each fault."""
import os
import subprocess
import sys
import tempfile

CHECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "layering.py")


def run(files):
    with tempfile.TemporaryDirectory() as src:
        for path, text in files.items():
            os.makedirs(os.path.dirname(os.path.join(src, path)), exist_ok=True)
            with open(os.path.join(src, path), "w", encoding="utf-8") as f:
                f.write(text)
        r = subprocess.run([sys.executable, CHECK, src], capture_output=True, text=True)
        return r.returncode, r.stdout


def main():
    clean = {"a/x.h": '#include "b/y.h"\n#include <vector>\n', "b/y.h": '#include "c/z.h"\n', "c/z.h": "",
             "a/x.cpp": '#include "x.h"\n#include "a/x.h"\n'}
    failures = []
    code, out = run(clean)
    if code != 0:
        failures.append(f"a clean tree failed: {out}")
    code, out = run({**clean, "c/z.cpp": '#include "a/x.h"\n'})
    if code != 1 or "include cycle between a, b, c" not in out or "c/z.cpp -> a/x.h" not in out:
        failures.append(f"a cycle through three folders was not reported: {code} {out}")
    code, out = run({**clean, "b/y.cpp": '#include <mpi.h>\n'})
    if code != 1 or "b/y.cpp includes mpi.h" not in out:
        failures.append(f"an MPI include was not reported: {code} {out}")
    for f in failures:
        print(f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
