#!/usr/bin/env python3
"""The function-length check against made-up sources: bodies at the limit pass, one line more
fails, lambdas and blocks count towards their function, and classes, namespaces and control
statements are not functions."""
import os
import subprocess
import sys
import tempfile

CHECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "function_length.py")


def body(lines):
    """A function whose body spans `lines` lines, braces included."""
    return "int f(int a) {\n" + "  a += 1;\n" * (lines - 2) + "}\n"


def run(text, limit=10):
    with tempfile.TemporaryDirectory() as src:
        with open(os.path.join(src, "x.cpp"), "w", encoding="utf-8") as f:
            f.write(text)
        r = subprocess.run([sys.executable, CHECK, "--max", str(limit), src], capture_output=True, text=True)
        return r.returncode, r.stdout


def main():
    failures = []
    code, out = run(body(10))
    if code != 0:
        failures.append(f"a body of 10 lines at a limit of 10 failed: {out}")
    code, out = run(body(11))
    if code != 1 or "a function of 11 lines" not in out:
        failures.append(f"a body of 11 lines was not reported: {code} {out}")
    lambda_inside = "void g() {\n  auto h = [](int x) {\n" + "    x += 1;\n" * 8 + "    return x;\n  };\n  h(1);\n}\n"
    code, out = run(lambda_inside)
    if code != 1 or "x.cpp:1:" not in out:
        failures.append(f"a lambda's lines were not counted towards its function: {code} {out}")
    not_functions = ("namespace n {\nstruct S {\n  int a = 0;\n};\n" +
                     "".join(f"int v{i} = {i};\n" for i in range(12)) + "}  // namespace n\n")
    code, out = run(not_functions)
    if code != 0:
        failures.append(f"a namespace of 15 lines was taken for a function: {out}")
    commented = "int f() {\n  /*\n" + "  {\n" * 12 + "  */\n  return 0; // }\n}\n"
    code, out = run(commented, limit=20)
    if code != 0:
        failures.append(f"braces in comments were counted: {out}")
    for f in failures:
        print(f)
    return int(bool(failures))


if __name__ == "__main__":
    sys.exit(main())
