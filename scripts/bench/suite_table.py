#!/usr/bin/python3
"""The equal-time suite table (docs/img/suite.md) from suite.sh's rows (docs/img/suite.csv).

Per scene and length: each configuration's RMSE against the reference as the root of its mean
squared error over the seeds (each seed's in brackets), and vcm's efficiency (MSE x time at equal
time) over bdpt and over the better of pssmlt and relt, from those mean squared errors.
Usage: suite_table.py SUITE_CSV OUT_MD
"""
import csv
import sys
from collections import defaultdict


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
    head = ["scene", "seconds"] + configs + ["vcm over bdpt", "vcm over best of pssmlt, relt"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for scene in scenes:
        for secs in sorted(scenes[scene]):
            cells, mse = [scene, str(secs)], {}
            for c in configs:
                v = rmse.get((scene, secs, c))
                if not v:
                    cells.append("-")
                    continue
                mse[c] = mean_square(v)
                cells.append("%.4g (%s)" % (mse[c] ** 0.5, ", ".join("%.4g" % x for x in v)))
            vcm = mse.get("vcm")
            cells.append("%.2f" % (mse["bdpt"] / vcm) if vcm and "bdpt" in mse else "-")
            chains = [mse[c] for c in ("pssmlt", "relt") if c in mse]
            cells.append("%.2f" % (min(chains) / vcm) if vcm and chains else "-")
            lines.append("| " + " | ".join(cells) + " |")
    with open(out_path, "w") as f:
        f.write("Equal time on 2 ranks against scenes/references (RMSE: root of the mean squared error over "
                "the seeds, each seed's in brackets); commits %s\n\n" % ", ".join(sorted(commits)))
        f.write("\n".join(lines) + "\n")
    print(open(out_path).read())


if __name__ == "__main__":
    main(*sys.argv[1:3])
