#!/usr/bin/env python3
"""Every doctest test case is a ctest test that runs it.

doctest_discover_tests hands each name to ctest as a CMake list, so a ';' splits one test case into
two ctest tests whose filters match no test case: both pass having run nothing. This fails on any
TEST_CASE name (its first string literal) with a ';' in it, naming the file and line."""
import pathlib
import re
import sys

NAME = re.compile(r'\bTEST_CASE(?:_FIXTURE)?\s*\((?:[^"()]*,)?\s*"((?:[^"\\]|\\.)*)"')


def main(root):
    bad = []
    for folder in ("tests", "examples"):
        for path in sorted((root / folder).rglob("*.cpp")):
            text = path.read_text(encoding="utf-8", errors="replace")
            for match in NAME.finditer(text):
                if ";" in match.group(1):
                    line = text.count("\n", 0, match.start()) + 1
                    bad.append(f"{path.relative_to(root)}:{line}: test case name has a ';': \"{match.group(1)}\"")
    print("\n".join(bad) if bad else "every test case name is one ctest test")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(pathlib.Path(sys.argv[1])))
