#!/usr/bin/env python3
"""Checks a JUnit XML report of `crumple regress`: well-formed XML, the counts, and each failure's type and message.

    check_junit.py FILE TESTS FAILURES [CASE=TYPE:REGEX ...]

CASE=TYPE:REGEX: the test case CASE failed with <failure type="TYPE"> and a message matching REGEX.
Every test case not named must have passed. Exit code 0 when all holds, 1 otherwise (with the reason)."""
import re
import sys
import xml.etree.ElementTree as ET


def main(argv):
    path, tests, failures = argv[1], int(argv[2]), int(argv[3])
    expected = {}
    for arg in argv[4:]:
        name, rest = arg.split("=", 1)
        expected[name] = rest.split(":", 1)
    root = ET.parse(path).getroot()  # raises on XML that is not well-formed
    suite = root.find("testsuite")
    problems = []
    if root.tag != "testsuites" or suite is None:
        problems.append("no <testsuites><testsuite>")
    else:
        for element in (root, suite):
            if (int(element.get("tests")), int(element.get("failures"))) != (tests, failures):
                problems.append(f"<{element.tag}> tests={element.get('tests')} failures={element.get('failures')}, "
                                f"expected {tests} and {failures}")
        cases = suite.findall("testcase")
        if len(cases) != tests:
            problems.append(f"{len(cases)} <testcase>, expected {tests}")
        for case in cases:
            failure = case.find("failure")
            name = case.get("name")
            if name not in expected:
                if failure is not None:
                    problems.append(f"{name} failed: {failure.get('message')}")
                continue
            kind, regex = expected.pop(name)
            if failure is None:
                problems.append(f"{name} passed, expected a failure")
            elif failure.get("type") != kind or not re.search(regex, failure.get("message")):
                problems.append(f"{name}: type {failure.get('type')!r} message {failure.get('message')!r}, "
                                f"expected {kind!r} and /{regex}/")
        problems += [f"no test case {name}" for name in expected]
    for p in problems:
        print(f"{path}: {p}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
