#!/usr/bin/env python3
"""Every doctest test case is a ctest test of its own name, labelled with its doctest suite.

scripts/test leaves the cases labelled `statistical` out of the sanitizer stage, so a case whose
label is lost runs there for minutes; and a case registered under the wrong name runs nothing. This
reads each TEST_CASE of tests/ and examples/ (its name: the string literals before the first
`*` or `)`; its suite: `doctest::test_suite("...")`) and checks, against `ctest -N` of the build
tree, that one test is named PREFIX/name and carries that suite as a label. Usage:
check_test_names.py SOURCE_DIR BUILD_DIR"""
import json
import pathlib
import re
import subprocess
import sys

LITERAL = r'"((?:[^"\\]|\\.)*)"'
CASE = re.compile(r'\bTEST_CASE(?:_FIXTURE)?\s*\((?:\s*\w+\s*,)?((?:\s*' + LITERAL + r')+)\s*(\*\s*doctest::test_suite\(\s*' +
                  LITERAL + r'\s*\))?')


def unescape(literal):
    return re.sub(r'\\(.)', r'\1', literal)


def source_cases(root):
    for folder in ("tests", "examples"):
        for path in sorted((root / folder).rglob("*.cpp")):
            text = path.read_text(encoding="utf-8", errors="replace")
            for match in CASE.finditer(text):
                name = "".join(unescape(part) for part in re.findall(LITERAL, match.group(1)))
                suite = unescape(match.group(4)) if match.group(4) is not None else None
                line = text.count("\n", 0, match.start()) + 1
                yield f"{path.relative_to(root)}:{line}", name, suite


def registered_tests(build):
    listing = subprocess.run(["ctest", "--test-dir", str(build), "-N", "--show-only=json-v1"], check=True,
                             capture_output=True, text=True).stdout
    tests = {}
    for test in json.loads(listing)["tests"]:
        labels = next((p["value"] for p in test.get("properties", []) if p["name"] == "LABELS"), [])
        tests[test["name"]] = set(labels)
    return tests


def main(root, build):
    tests = registered_tests(build)
    # A discovered case is PREFIX/name; the prefix is the suite binary's (render/, lpe/, ...).
    by_name = {}
    for full, labels in tests.items():
        prefix, _, name = full.partition("/")
        by_name.setdefault(name, []).append((full, labels))
    bad = []
    count = 0
    for where, name, suite in source_cases(root):
        count += 1
        found = by_name.get(name, [])
        if not found:
            bad.append(f"{where}: no ctest test is named */{name!r}")
        elif suite is not None and not any(suite in labels for _, labels in found):
            bad.append(f"{where}: {found[0][0]!r} is not labelled {suite!r} (its labels: {sorted(found[0][1])})")
    if count == 0:
        bad.append("no TEST_CASE found in tests/ or examples/")
    print("\n".join(bad) if bad else f"every one of {count} test cases is a ctest test of its name, with its suite's label")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])))
