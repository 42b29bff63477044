"""The result files the report scripts read (bench_table.py, bench_ratios.py): the files named, and
every file ending in `suffix` in the folders named, folders in sorted order."""
import os
import sys


def result_files(paths, suffix, program):
    """The files in `paths` (files, or folders of *suffix); exits naming `program` when none."""
    files = []
    for p in paths:
        if os.path.isdir(p):
            files += sorted(os.path.join(p, f) for f in os.listdir(p) if f.endswith(suffix))
        else:
            files.append(p)
    if not files:
        sys.exit("%s: no %s files in %s" % (program, suffix, " ".join(paths)))
    return files
