#!/usr/bin/env python3
"""Query every Parquet table of a study output folder with pyarrow, pandas,
polars and DuckDB: read it, sort it by its id column and filter it on a text
column, and check all four tools agree. Reports every table; exits 1 if any
table fails (runs and summary must exist), 2 on bad usage.

Usage: python3 tests/arrow_tools.py OUTPUT_FOLDER
(needs: pip install pyarrow pandas polars duckdb)
"""

import sys
from pathlib import Path

import duckdb
import pandas as pd
import polars as pl
import pyarrow.compute as pc
import pyarrow.parquet as pq

# table -> (id column to sort by, text column to filter on, required)
TABLES = {
    "runs": ("run_id", "status", True),
    "series": ("run_id", "observable", False),
    "histograms": ("run_id", "observable", False),
    "summary": ("point_id", "result", True),
}


def check_table(path, key, text):
    """Query one table with each tool; return a line describing what passed."""
    # pyarrow: the stored schema, sort_by, filter with pc.equal.
    table = pq.read_table(path)
    views = [f"{f.name}: {f.type}" for f in table.schema if "view" in str(f.type)]
    if views:
        raise AssertionError(f"view types in the schema: {views}")
    if str(table.schema.field(text).type) not in ("string", "large_string"):
        raise AssertionError(f"{text} is {table.schema.field(text).type}, not text")
    value = table[text][0].as_py()
    ordered = table.sort_by(key)
    keys = ordered[key].to_pylist()
    if keys != sorted(keys):
        raise AssertionError(f"pyarrow sort_by({key!r}) is not sorted")
    mask = pc.equal(ordered[text], value)
    expected = ordered.filter(mask)
    n = expected.num_rows
    if n == 0:
        raise AssertionError(f"pyarrow: no row with {text} == {value!r}")
    expected_keys = expected[key].to_pylist()

    # pandas: read, sort, filter.
    frame = pd.read_parquet(path)
    frame = frame.sort_values(key, kind="stable")
    frame = frame[frame[text] == value]
    if frame[key].tolist() != expected_keys:
        raise AssertionError("pandas disagrees with pyarrow")

    # polars: read, filter, sort.
    pframe = pl.read_parquet(path).filter(pl.col(text) == value).sort(key, maintain_order=True)
    if pframe[key].to_list() != expected_keys:
        raise AssertionError("polars disagrees with pyarrow")

    # DuckDB: SQL straight on the file.
    rows = duckdb.execute(
        f'SELECT "{key}" FROM read_parquet(?) WHERE "{text}" = ? ORDER BY "{key}"',
        [str(path), value],
    ).fetchall()
    if [r[0] for r in rows] != expected_keys:
        raise AssertionError("DuckDB disagrees with pyarrow")

    return (
        f"{path.name}: {table.num_rows} rows; {text} == {value!r}: {n} rows, "
        f"same in pyarrow, pandas, polars, DuckDB"
    )


def main():
    if len(sys.argv) != 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    folder = Path(sys.argv[1])
    failed = False
    for name, (key, text, required) in TABLES.items():
        path = folder / f"{name}.parquet"
        if not path.exists():
            if required:
                print(f"FAIL {path}: missing")
                failed = True
            continue
        try:
            print("ok  ", check_table(path, key, text))
        except Exception as e:  # report every table, then fail
            print(f"FAIL {path}: {type(e).__name__}: {e}")
            failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
