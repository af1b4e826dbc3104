#!/usr/bin/python3
"""The equal-time suite table (docs/img/suite.md) from suite.sh's rows (docs/img/suite.csv).

Per scene and length: each configuration's RMSE against the reference as the root of its mean
squared error over the seeds (each seed's in brackets), and the efficiency (MSE x time at equal
time) of vcm over bdpt and over the better of pssmlt and relt, and of meb over vcm and over the best
of bdpt, pssmlt, mmlt and relt (where those rows exist), from those mean squared errors. Where the
reference's JSON states its own error (reference_rmse_estimate), the efficiencies are also given with
that error's square taken out of every MSE (a reference's noise adds to every render's MSE alike and
so pulls every ratio towards 1).
Usage: suite_table.py SUITE_CSV OUT_MD
"""
import csv
import json
import os
import sys
from collections import defaultdict

REFERENCES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenes", "references")


def reference_mse(scene):
    """The square of the reference's own RMSE estimate, or None where its JSON states none."""
    path = os.path.join(REFERENCES, scene + ".json")
    try:
        estimate = json.load(open(path)).get("reference_rmse_estimate")
    except OSError:
        return None
    return estimate * estimate if estimate else None


# (subject, the configurations it is measured against: their best) per efficiency column.
COLUMNS = [("vcm", ["bdpt"]), ("vcm", ["pssmlt", "relt"]), ("meb", ["vcm"]), ("meb", ["bdpt", "pssmlt", "mmlt", "relt"])]


def efficiencies(mse, ref_mse):
    """Each column's subject over the best of its others (MSE ratio at equal time); ref_mse is taken
    out of each MSE first."""
    own = {c: m - ref_mse for c, m in mse.items()}
    cells = []
    for subject, others in COLUMNS:
        best = [own[c] for c in others if c in own]
        ok = subject in own and own[subject] > 0.0 and best
        cells.append("%.2f" % (min(best) / own[subject]) if ok else "-")
    return cells


def mean_square(values):
    return sum(v * v for v in values) / len(values)


def main(csv_path, out_path):
    rows = list(csv.DictReader(open(csv_path)))
    rmse = defaultdict(list)  # (scene, seconds, configuration) -> each seed's RMSE
    scenes, configs, commits = {}, {}, set()
    for r in rows:
        rmse[(r["scene"], int(float(r["seconds"])), r["configuration"])].append(float(r["rmse"]))
        scenes.setdefault(r["scene"], set()).add(int(float(r["seconds"])))
        configs[r["configuration"]] = True
        commits.add(r["commit"])
    configs = list(configs)
    head = ["scene", "seconds"] + configs + ["%s over %s" % (s, " / ".join(o) if len(o) == 1 else "best of " + ", ".join(o))
                                             for s, o in COLUMNS] + ["reference's RMSE", "the same, its MSE taken out"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for scene in scenes:
        ref_mse = reference_mse(scene)
        for secs in sorted(scenes[scene]):
            cells, mse = [scene, str(secs)], {}
            for c in configs:
                v = rmse.get((scene, secs, c))
                if not v:
                    cells.append("-")
                    continue
                mse[c] = mean_square(v)
                cells.append("%.4g (%s)" % (mse[c] ** 0.5, ", ".join("%.4g" % x for x in v)))
            cells += efficiencies(mse, 0.0)
            if ref_mse is None:
                cells += ["not stated", "-"]
            else:
                cells += ["%.4g" % ref_mse ** 0.5, " / ".join(efficiencies(mse, ref_mse))]
            lines.append("| " + " | ".join(cells) + " |")
    with open(out_path, "w") as f:
        f.write("Equal time on 2 ranks against scenes/references (RMSE: root of the mean squared error over "
                "the seeds, each seed's in brackets); commits %s\n\n" % ", ".join(sorted(commits)))
        f.write("\n".join(lines) + "\n")
    print(open(out_path).read())


if __name__ == "__main__":
    main(*sys.argv[1:3])
