#!/usr/bin/env python3
"""Compare the tables of two study folders, all columns but the timings.

Usage: compare.py A B. Prints one line per table and exits 1 unless every
table of A is in B with the same columns and the same values (NaN equals
NaN: a missing value of a run is the same whatever machine computed it).
"""
import math
import sys

import pyarrow.parquet as pq

TABLES = ["runs", "series", "histograms", "summary"]
TIMINGS = {"wall_seconds", "cpu_seconds", "prepare_seconds"}


def same(x, y):
    if isinstance(x, float) and isinstance(y, float):
        return (math.isnan(x) and math.isnan(y)) or x == y
    return x == y


def main(a, b):
    ok = True
    for name in TABLES:
        path_a, path_b = f"{a}/{name}.parquet", f"{b}/{name}.parquet"
        try:
            ta = pq.read_table(path_a)
        except FileNotFoundError:
            continue
        tb = pq.read_table(path_b)
        cols = [c for c in ta.column_names if c not in TIMINGS]
        equal = cols == [c for c in tb.column_names if c not in TIMINGS]
        equal = equal and ta.num_rows == tb.num_rows
        for c in cols if equal else []:
            xs, ys = ta.column(c).to_pylist(), tb.column(c).to_pylist()
            if not all(same(x, y) for x, y in zip(xs, ys)):
                print(f"{name}.parquet: column {c} differs")
                equal = False
        print(f"{name}.parquet: {ta.num_rows} rows, {'identical' if equal else 'DIFFERENT'}")
        ok = ok and equal
    print("ALL IDENTICAL" if ok else "TABLES DIFFER")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
