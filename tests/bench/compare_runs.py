#!/usr/bin/env python3
"""Compares satviz-bench outputs of two builds, row by row.

Usage: compare_runs.py BEFORE[,BEFORE...] AFTER[,AFTER...]

Each argument is a comma-separated list of files that one build's `satviz-bench` wrote (the same command for both
builds). A table row is a label followed by numbers (or '-'); rows are matched by their label within the section
they stand in (the line above a table names it). For each row present in every file, the script prints after /
before column by column, each side the mean over its files: below 1 the after build is faster in an 'ns per query'
table, and a measured ratio fell in a 'ratios' table. The peers' rows (Box2D, Chipmunk) are the same code in both
builds: how far they stray from 1 is how much the machine differed between the runs.
"""
import re
import statistics
import sys

NUMBER = re.compile(r'^-?[0-9.]+(e[+-]?[0-9]+)?$')


def parse(path):
    """Rows of one output, keyed by (section, label): their numbers, None for '-'."""
    rows = {}
    section = ''
    with open(path, encoding='utf-8') as f:
        for line in f:
            tokens = line.split()
            if not tokens:
                continue
            i = len(tokens)
            while i > 0 and (NUMBER.match(tokens[i - 1]) or tokens[i - 1] == '-'):
                i -= 1
            label = ' '.join(tokens[:i])
            values = tokens[i:]
            if label and len(values) >= 3:
                rows[(section, label)] = [None if v == '-' else float(v) for v in values]
            else:
                section = line.strip()[:60]
    return rows


def mean_row(runs, key):
    """The mean of a row over runs, column by column (None where any run has no number)."""
    columns = zip(*(run[key] for run in runs))
    return [None if any(c is None for c in column) else statistics.mean(column) for column in columns]


def main(argv):
    if len(argv) != 3:
        sys.exit('usage: compare_runs.py BEFORE[,BEFORE...] AFTER[,AFTER...]')
    before = [parse(p) for p in argv[1].split(',')]
    after = [parse(p) for p in argv[2].split(',')]
    print(f'after / before, each the mean of its runs\nbefore: {argv[1]}\nafter:  {argv[2]}')
    section = None
    for key in before[0]:
        if not all(key in run for run in before + after):
            continue
        if key[0] != section:
            section = key[0]
            print(f'\n## {section}')
        cells = []
        for b, a in zip(mean_row(before, key), mean_row(after, key)):
            cells.append('    - ' if b is None or a is None or b == 0 else f'{a / b:6.3f}')
        print(f'{key[1][:48]:48s}|' + ' '.join(cells))


if __name__ == '__main__':
    main(sys.argv)
