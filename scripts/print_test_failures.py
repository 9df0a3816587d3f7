#!/usr/bin/env python3
"""Prints why each failed test failed: the <failure>/<error> text of every
JUnit XML file under a test results folder (catkin's test_results), so the
end of a CI log says which check broke and with what values, not only how
many did.

Usage: print_test_failures.py TEST_RESULTS_DIR [--lines N]
"""
import argparse
import pathlib
import sys
import xml.etree.ElementTree as ET


def failures(path):
    """(test case name, failure text) of each failed test case in one file."""
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        yield path.name, 'unreadable result file: %s' % e
        return
    for case in root.iter('testcase'):
        for bad in list(case.findall('failure')) + list(case.findall('error')):
            text = (bad.text or '').strip() or bad.get('message', '')
            yield '%s.%s' % (case.get('classname', ''), case.get('name', '')), text


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('results', type=pathlib.Path, help='folder of JUnit XML files (searched recursively)')
    parser.add_argument('--lines', type=int, default=25, help='lines of each failure to print (default 25)')
    args = parser.parse_args()
    if not args.results.is_dir():
        parser.error('%s is not a folder of test results' % args.results)
    found = 0
    for path in sorted(args.results.rglob('*.xml')):
        for name, text in failures(path):
            found += 1
            lines = text.splitlines()
            print('--- %s (%s)' % (name, path.relative_to(args.results)))
            if len(lines) > args.lines:
                # The first line says what broke; a traceback's end says where.
                tail = max(args.lines - 1, 0)
                lines = lines[:1] + ['... (%d lines, all in %s)' % (len(lines) - 1 - tail, path)] + \
                    (lines[-tail:] if tail else [])
            print('\n'.join(lines))
    return 0 if found == 0 else 1


if __name__ == '__main__':
    sys.exit(main())
