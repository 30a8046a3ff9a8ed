#!/usr/bin/env python3
"""Compares what one program printed on several targets (tests/platforms.sh).

    compare_outputs.py NAME=FILE NAME=FILE [NAME=FILE ...]

The first file is the reference. Line by line, after dropping a Windows carriage return:
every number must agree with the reference's to 1e-12 relative (|a - b| <= 1e-12 max(|a|, |b|))
and the text around the numbers must be the same. Lines starting with "build " say what a
build contains and may differ; lines starting with "bits " (platform_check's digests of raw
state) are reported, equal or not, but do not fail the comparison: equal digests mean
bitwise equal results, and only the 1e-12 is promised across targets (their libm may round
sin and cos otherwise). Prints one line per target; exits 1 if any target disagrees.
"""
import re
import sys

TOLERANCE = 1e-12
# A number, not part of a word (the "NaN" of a message, the "64" of "x86-64_v3").
NUMBER = re.compile(r"(?<![\w.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?![\w.])|"
                    r"(?<![\w.])[-+]?(?:nan|inf)(?![\w.])")


def read(path):
    with open(path, encoding="utf-8", newline="") as f:
        return [line.rstrip("\r\n").rstrip("\r") for line in f]


def split(line):
    """The text with each number replaced by #, and the numbers."""
    numbers = [float(m) for m in NUMBER.findall(line)]
    return NUMBER.sub("#", line), numbers


def compare(reference, other):
    """(problems, figures compared, largest relative difference, digests equal, digests)."""
    problems = []
    worst = 0.0
    figures = 0
    bits_equal = 0
    bits_total = 0
    if len(reference) != len(other):
        problems.append("%d lines against %d" % (len(other), len(reference)))
    for number, (a, b) in enumerate(zip(reference, other), start=1):
        if a.startswith("build ") and b.startswith("build "):
            continue
        if a.startswith("bits ") and b.startswith("bits "):
            bits_total += 1
            bits_equal += a == b
            continue
        text_a, values_a = split(a)
        text_b, values_b = split(b)
        if text_a != text_b or len(values_a) != len(values_b):
            problems.append("line %d differs:\n    %s\n    %s" % (number, a, b))
            continue
        figures += len(values_a)
        for x, y in zip(values_a, values_b):
            if x == y:
                continue
            scale = max(abs(x), abs(y))
            relative = abs(x - y) / scale if scale > 0 else float("inf")
            if not relative <= TOLERANCE:  # also catches a NaN
                problems.append("line %d: %r against %r (relative %.3g):\n    %s\n    %s"
                                % (number, y, x, relative, a, b))
            worst = max(worst, relative)
    return problems, figures, worst, bits_equal, bits_total


def main(argv):
    if len(argv) < 3 or any("=" not in arg for arg in argv[1:]):
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    runs = [arg.split("=", 1) for arg in argv[1:]]
    reference_name, reference_path = runs[0]
    reference = read(reference_path)
    failed = False
    for name, path in runs[1:]:
        problems, figures, worst, bits_equal, bits_total = compare(reference, read(path))
        if problems:
            failed = True
            print("compare: %s against %s: FAILED" % (name, reference_name))
            for problem in problems:
                print("  " + problem)
            continue
        if worst == 0.0:
            agreement = "every number equal"
        else:
            agreement = "largest relative difference %.2g" % worst
        digests = "bitwise equal" if bits_equal == bits_total else \
            "%d of %d state digests equal (not bitwise)" % (bits_equal, bits_total)
        print("compare: %s against %s: %d lines, %d numbers, %s (<= %g); %s"
              % (name, reference_name, len(reference), figures, agreement, TOLERANCE,
                 digests if bits_total else "no state digests"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
