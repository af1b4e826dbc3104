"""Plots of a scaling CSV (scripts/scaling/*.sh): python3 plot.py CSV strong|weak|sweep OUT.png.

strong, weak: round-loop time, parallel efficiency (strong: T1 / (P TP), weak: T1 / TP) and the
share of the loop inside collectives, against ranks (median run of each rank count); oversubscribed
points are hollow.
sweep: time and collective share against the exchange interval, one line per placement.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

path, kind, out = sys.argv[1], sys.argv[2], sys.argv[3]
rows = list(csv.DictReader(open(path)))
fig, axes = plt.subplots(1, 3 if kind != "sweep" else 2, figsize=(12 if kind != "sweep" else 8, 3.6))

if kind in ("strong", "weak"):
    # Median over repeated runs of each rank count.
    by = {}
    for r in rows:
        by.setdefault(int(r["ranks"]), []).append(r)
    rows = [sorted(v, key=lambda r: float(r["loop_seconds"]))[len(v) // 2] for _, v in sorted(by.items())]
    ranks = [int(r["ranks"]) for r in rows]
    time = [float(r["loop_seconds"]) for r in rows]
    share = [100 * float(r["collective_share_max"]) for r in rows]
    base = time[ranks.index(1)] if 1 in ranks else time[0]
    eff = [base / (p * t) if kind == "strong" else base / t for p, t in zip(ranks, time)]
    over = [r["oversubscribed"] == "1" for r in rows]
    for ax, ys, label in zip(axes, (time, eff, share),
                             ("round loop (s)", "parallel efficiency", "in collectives, worst rank (%)")):
        ax.plot(ranks, ys, "-", color="tab:blue")
        ax.scatter([p for p, o in zip(ranks, over) if not o], [y for y, o in zip(ys, over) if not o],
                   color="tab:blue", label="real cores")
        ax.scatter([p for p, o in zip(ranks, over) if o], [y for y, o in zip(ys, over) if o],
                   facecolors="none", edgecolors="tab:blue", label="oversubscribed")
        ax.set_xscale("log", base=2)
        ax.set_xlabel("ranks")
        ax.set_ylabel(label)
    axes[1].set_ylim(0, 1.1)
    axes[0].legend()
else:
    for placement, color in (("spread", "tab:blue"), ("packed", "tab:orange")):
        sel = [r for r in rows if r["placement"] == placement]
        k = [int(r["interval"]) for r in sel]
        axes[0].plot(k, [float(r["loop_seconds"]) for r in sel], "o-", color=color, label=placement)
        axes[1].plot(k, [100 * float(r["collective_share_max"]) for r in sel], "o-", color=color, label=placement)
    for ax, label in zip(axes, ("round loop (s)", "in collectives, worst rank (%)")):
        ax.set_xscale("log", base=2)
        ax.set_xlabel("exchange interval")
        ax.set_ylabel(label)
    axes[0].legend()
fig.suptitle(f"relt {kind} scaling" if kind != "sweep" else "relt: exchange interval and placement")
fig.tight_layout()
fig.savefig(out, dpi=110)
