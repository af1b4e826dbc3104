#!/usr/bin/env python3
"""Fails on a function body longer than a limit (default 80 lines) in the given source folders.

A function is a brace block opened after a parameter list `)` (possibly followed by qualifiers,
`-> type` or a constructor's initialisers) at namespace or class level; lambdas and blocks inside
count towards their function. Comments, strings and preprocessor lines are blanked first.
Usage: function_length.py [--max N] DIR...
"""
import argparse
import os
import re
import sys

TOKEN = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'|^\s*#[^\n]*', re.S | re.M)
NOT_A_FUNCTION = re.compile(r'\b(namespace|class|struct|union|enum)\b[^;{}()]*$|=\s*$|\b(if|for|while|switch|catch|do|else)\b')


def blank(text):
    """Comments, strings and preprocessor lines as spaces, keeping the line breaks."""
    return TOKEN.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def functions(text):
    """(first line, lines) of every function body in `text`."""
    code = blank(text)
    out, stack = [], []  # stack: (kind, line) per open brace, kind "f" for a function body
    line, last_stop = 1, 0
    for i, ch in enumerate(code):
        if ch == "\n":
            line += 1
        elif ch == "{":
            head = code[last_stop:i]
            inside_function = any(kind == "f" for kind, _ in stack)
            is_function = (not inside_function and re.search(r"\)[^;(){}]*$", head) is not None
                           and not NOT_A_FUNCTION.search(head.split(")")[0].split("\n")[-1] + ")" + head.split(")")[-1]))
            stack.append(("f" if is_function else "b", line))
            last_stop = i + 1
        elif ch == "}":
            if stack:
                kind, first = stack.pop()
                if kind == "f":
                    out.append((first, line - first + 1))
            last_stop = i + 1
        elif ch == ";":
            last_stop = i + 1
    return out


def sources(dirs):
    """Every .h and .cpp file under `dirs`, in a stable order."""
    for d in dirs:
        for root, _, files in sorted(os.walk(d)):
            for name in sorted(files):
                if name.endswith((".h", ".cpp")):
                    yield os.path.join(root, name)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--max", type=int, default=80)
    parser.add_argument("dirs", nargs="+")
    args = parser.parse_args()
    found = 0
    for path in sources(args.dirs):
        with open(path, encoding="utf-8") as f:
            for first, lines in functions(f.read()):
                if lines > args.max:
                    found += 1
                    print(f"{path}:{first}: a function of {lines} lines (at most {args.max})")
    return int(found > 0)


if __name__ == "__main__":
    sys.exit(main())
