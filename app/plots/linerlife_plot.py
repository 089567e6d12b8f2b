#!/usr/bin/python3
"""Draws the charts of a linerlife results file with matplotlib.

Usage: linerlife_plot.py KIND RESULTS.h5 OUT_DIR

KIND names a module plot_KIND.py next to this file whose draw(h5, out) makes
the charts. Every PNG is written under a temporary name, and the charts are
renamed together once all are drawn: a crash never leaves a half-written
picture, and a file that fails part-way leaves none. Needs Debian's python3-matplotlib
and python3-h5py (run with /usr/bin/python3).

Before drawing, the datasets the module's required_rows(h5) names must be
there with at least one row, and those its finite_datasets(h5) names are read
whole: a missing or empty one, or a NaN or an infinite value (a damaged file),
draws nothing.

Exit codes: 0 charts drawn; 3 the results file lacks a group, dataset or
attribute its kind has (damaged or not written by linerlife); 4 a dataset it
draws holds a value that is not a finite number: one line on the standard
output, "DATASET: what is wrong", for `linerlife plot` to name it; 5 a chart
could not be written (one line on the standard output: the file and the
system's reason, e.g. a folder in the way); 2 usage or an unknown kind;
anything else (1: a missing package) the environment.
"""
import importlib
import os
import sys

import matplotlib

matplotlib.use("Agg")


def main(argv):
    if len(argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    kind, results, out = argv[1:]
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    try:
        module = importlib.import_module("plot_" + kind)
    except ImportError as e:
        print(f"linerlife_plot: no charts for '{kind}': {e}", file=sys.stderr)
        return 2
    import h5py

    from plot_common import NotFinite, check_finite, commit_charts, discard_charts

    with h5py.File(results, "r") as h5:
        try:
            # the datasets a chart needs rows of: missing or empty, the file is incomplete
            for path in (module.required_rows(h5) if hasattr(module, "required_rows") else []):
                if len(h5[path]) == 0:
                    raise KeyError(f"{path} is empty")
            check_finite(h5, module.finite_datasets(h5) if hasattr(module, "finite_datasets") else [])
            module.draw(h5, out)
            commit_charts(out, getattr(module, "CHARTS", ()))  # all the charts, or none
        except KeyError as e:  # h5py: a missing object or attribute
            print(f"linerlife_plot: {results} is damaged or incomplete for a {kind} results file: {e}", file=sys.stderr)
            return 3
        except NotFinite as e:  # nothing drawn yet
            print(e, flush=True)
            return 4
        except OSError as e:  # a chart could not be written (save() left no temporary)
            print(f"cannot write {e.filename or out}: {e.strerror or e}", flush=True)
            return 5
        finally:
            discard_charts()  # the temporaries of a file that failed part-way
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
