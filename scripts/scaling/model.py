"""Cost model of relt's round loop (docs/SCALING.md): predicted parallel efficiency against ranks.

python3 model.py STATS.json COLLECTIVES.jsonl OUT.md OUT.png [--alpha SECONDS] [--bandwidth BYTES_PER_S]
                [--chains-per-rank N ...] [--seed S] [--summary FILE --label TEXT]

STATS.json: a 2-rank relt render with spread placement and --stats (per-rank stepping time of
every group round, time deciding the exchanges, time in collectives); COLLECTIVES.jsonl:
relt_bench_collectives on 2 ranks (copy bandwidth of this machine). --alpha/--bandwidth: the
cluster network's latency per message step and bandwidth (defaults: 2 us, 12 GB/s, an
InfiniBand EDR-class fabric).

Weak scaling in chains: every rank keeps N chains (default: as measured, and twice that). Waiting
is simulated (round_sim.py): P ranks' stepping times are cut from the measured traces (blocks of
64 group rounds, so slow phases stay together) and run through the protocol; its replay of the
two measured traces is checked against the two ranks' measured time in collectives. Twice the
chains: each group round sums two independent runs. Three noise cases: as measured on this VM;
without stalls (group rounds clipped at 3x the median: no preemption); without stalls or drift
(clipped, then shuffled within each rank: only round-to-round jitter). The other costs of a group
round, per protocol:
  blocking-spread   one blocking allgather of every chain's targets per round, every rank decides
                    every ladder's exchange
  staggered-spread  (relt up to 8 ranks) the same messages and decisions, rounds of two ladder
                    groups half a round apart: network time hides behind the other group's work,
                    decisions and copying the gathered targets do not
  sub-communicators spread, but each ladder exchanges on its own communicator of M ranks: a rank
                    takes part in one small collective per hosted chain per round
  staggered-packed  whole ladders per rank, decisions local, messages of M + 4 numbers per rank,
                    every round waits for the slowest rank (relt above 8 ranks with
                    --normaliser-lag 1)
  lagged-packed D   the same with the sums read back D rounds late (--normaliser-lag D
                    --normaliser-lag-growth 0; relt's default above 8 ranks starts at D = 32 and
                    grows, see Render length): a group waits for its collective of D rounds ago,
                    so a rank may run D rounds ahead
Render length: efficiency at 1,024 ranks of a fixed lag of 32 (relt's default until 2026-12-01),
of relt's default lag growing with the render (max(32, min(256, R / 8)) at round R,
--normaliser-lag-growth 8) and of the unlimited lag, for renders a
multiple (--lengths) of the measured one, built from independent blocks of 64 group rounds (and,
to show how much that assumption matters, of 512).
  unlimited lag     the bound of every lagged protocol: ranks never wait for each other before the
                    end (no protocol of relt; the render still ends when the slowest rank does)
"""
import argparse
import json
import math
import os
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import round_sim  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("stats")
ap.add_argument("collectives")
ap.add_argument("--trace", required=True, help="the render's --trace file (stepping time of every group round)")
ap.add_argument("out_md")
ap.add_argument("out_png")
ap.add_argument("--alpha", type=float, default=2e-6)
ap.add_argument("--bandwidth", type=float, default=12e9)
ap.add_argument("--chains-per-rank", type=int, nargs="*")
ap.add_argument("--seed", type=int, default=1)
ap.add_argument("--summary", help="append this run's row (1,024 ranks, measured chains per rank) to FILE")
ap.add_argument("--label", default="")
ap.add_argument("--lengths", type=int, nargs="*", default=[1, 4, 16],
                help="render lengths, as multiples of the measured one, for the render-length table")
ap.add_argument("--length-summary", help="append this run's render-length row (1,024 ranks) to FILE")
a = ap.parse_args()

j = json.load(open(a.stats))
r = j["relt"]
s = j["settings"]
ranks0 = j["ranks"]
levels = len(r["levels"])
groups = r["groups"]
interval = s["exchange_interval"]
measured_chains = s["ladders"] * levels / ranks0
traces = [np.asarray(t, dtype=float) for t in json.load(open(a.trace))["group_round_step_seconds_per_rank"]]
t_g0 = float(np.mean([t.mean() for t in traces]))  # stepping a group round
sigma0 = float(np.mean([t.std() for t in traces]))
t_ladder = sum(r["group_round_finish_seconds_mean_per_rank"]) / ranks0 / (s["ladders"] / groups)
measured_share = [c / r["loop_seconds"] for c in r["round_collective_seconds_per_rank"]]
coll = [json.loads(line) for line in open(a.collectives) if line.strip()]
big = max(coll, key=lambda c: c["doubles_per_rank"])
copy_bw = big["doubles_per_rank"] * 8 * big["ranks"] / big["allgatherv_seconds"]  # bytes/s, this machine
counts = a.chains_per_rank or [int(measured_chains), int(2 * measured_chains)]
BLOCK = 64 * groups
n_measured = min(map(len, traces)) // BLOCK * BLOCK  # group rounds per rank the bootstrap keeps

median = float(np.median(np.concatenate(traces)))
clipped = [np.minimum(t, 3 * median) for t in traces]
rng0 = np.random.default_rng(a.seed)
shuffled = [rng0.permutation(t) for t in clipped]
noises = {"as measured": traces, "no stalls": clipped, "no stalls, no drift": shuffled}
protocols = ["blocking-spread", "staggered-spread", "sub-communicators", "staggered-packed",
             "lagged-packed D=8", "lagged-packed D=32", "unlimited lag"]  # relt: spread up to 8 ranks, then a lag growing from 32
ps = [2 ** k for k in range(1, 13, 1)]


def allgather(p, total_bytes):
    """Network time of an allgather (recursive doubling / ring): latency log2 P, all bytes once."""
    return a.alpha * math.ceil(math.log2(p)) + total_bytes / a.bandwidth if p > 1 else 0.0


def overhead(protocol, p, chains_rank, t_g):
    """Per group round: work besides stepping that does not hide behind the other group."""
    ladders_rank_group = chains_rank / levels / groups
    if protocol == "blocking-spread":  # one collective per round (all groups): its share
        msg = p * (chains_rank * levels + levels + 4) * 8
        return p * ladders_rank_group * t_ladder + (msg / copy_bw + allgather(p, msg)) / groups
    if protocol == "staggered-spread":
        msg = p * (chains_rank / groups * levels + levels + 4) * 8
        return p * ladders_rank_group * t_ladder + msg / copy_bw + max(0.0, allgather(p, msg) - t_g)
    if protocol == "sub-communicators":
        per = chains_rank / groups * (a.alpha * math.ceil(math.log2(levels)) + levels * levels * 8 / a.bandwidth)
        return ladders_rank_group * t_ladder + per
    msg = p * (levels + 4) * 8  # packed, lagged or not
    return ladders_rank_group * t_ladder + msg / copy_bw + max(0.0, allgather(p, msg) - t_g)


def simulated(protocol, sample):
    if protocol == "blocking-spread":
        return round_sim.blocking(sample, groups)
    lag = int(protocol.split("D=")[1]) if "D=" in protocol else 1
    if protocol == "unlimited lag":
        lag = sample.shape[1]  # beyond the last round: no group ever waits before the end
    return round_sim.staggered(sample, groups, lag=lag)


def predict(noise, chains_rank):
    """{protocol: [efficiency at each P]}: simulated waiting plus the protocol's other costs."""
    rng = np.random.default_rng(a.seed)
    copies = max(1, round(chains_rank / measured_chains))
    out = {x: [] for x in protocols}
    for p in ps:
        sample = round_sim.bootstrap(noises[noise], p, groups, BLOCK, rng, copies=copies)
        t_g = float(sample.mean())
        for x in protocols:
            # The simulation's efficiency t_g / (t_g + wait), then the other costs on top.
            out[x].append(1.0 / (1.0 / simulated(x, sample) + overhead(x, p, chains_rank, t_g) / t_g))
    return out


def by_length(block):
    """{protocol: [efficiency at 1,024 ranks for each of a.lengths]}, as measured, measured chains per
    rank: a longer render is a longer run of independent blocks of `block` group rounds."""
    lags = {"lagged-packed D=32": 32, "growing lag (default)": lambda r: max(32, min(256, r // 8)), "unlimited lag": None}
    out = {x: [] for x in lags}
    for k in a.lengths:
        sample = round_sim.bootstrap(traces, 1024, groups, block, np.random.default_rng(a.seed), length=k * n_measured)
        t_g = float(sample.mean())
        for x, lag in lags.items():
            eff = round_sim.staggered(sample, groups, lag=sample.shape[1] if lag is None else lag)
            out[x].append(1.0 / (1.0 / eff + overhead(x, 1024, int(measured_chains), t_g) / t_g))
    return out


replay = round_sim.staggered(np.vstack([t[: min(map(len, traces))] for t in traces]), groups)
results = {(noise, n): predict(noise, n) for noise in noises for n in counts}
seconds0 = n_measured * t_g0  # the measured render's stepping time
lengths = by_length(BLOCK)
long_blocks = by_length(8 * BLOCK)
with open(a.out_md, "w") as f:
    f.write("Measured inputs (2 ranks, %s, %d chains per rank, %d levels, interval %d, %d group rounds "
            "traced per rank): stepping a group round t_g = %.3f ms, its spread %.3f ms (%.1f %%), "
            "longest %.1f ms; deciding one ladder's exchange %.2f us; this machine's copy bandwidth "
            "%.1f GB/s. Network: latency %.1f us per step, %.0f GB/s.\n\n"
            % (s["scene"].split("/")[-1], measured_chains, levels, interval, len(traces[0]), t_g0 * 1e3,
               sigma0 * 1e3, 100 * sigma0 / t_g0, max(t.max() for t in traces) * 1e3, t_ladder * 1e6,
               copy_bw / 1e9, a.alpha * 1e6, a.bandwidth / 1e9))
    f.write("Check: replaying the two measured traces through the staggered loop gives %.1f %% "
            "efficiency; the ranks measured %s in collectives (waiting and the calls themselves).\n"
            % (100 * replay, " and ".join("%.1f %%" % (100 * x) for x in measured_share)))
    for (noise, n), res in results.items():
        f.write("\nPredicted efficiency, %s, %d chains per rank:\n\n" % (noise, n))
        f.write("| ranks | " + " | ".join(protocols) + " |\n|---|" + "---|" * len(protocols) + "\n")
        for i, p in enumerate(ps):
            f.write("| %d | " % p + " | ".join("%.1f %%" % (100 * res[x][i]) for x in protocols) + " |\n")
    f.write("\nRender length (as measured, %d chains per rank, 1,024 ranks; a longer render is a longer "
            "run of independent blocks of %d group rounds, in brackets of %d; the measured traces "
            "cover %.1f s of stepping):\n\n" % (measured_chains, BLOCK, 8 * BLOCK, seconds0))
    f.write("| length | stepping s | " + " | ".join(lengths) + " |\n|---|---|" + "---|" * len(lengths) + "\n")
    for i, k in enumerate(a.lengths):
        f.write("| %dx | %.0f | " % (k, k * seconds0) + " | ".join(
            "%.1f %% (%.1f %%)" % (100 * lengths[x][i], 100 * long_blocks[x][i]) for x in lengths) + " |\n")
fig, axes = plt.subplots(len(counts), len(noises), figsize=(5.5 * len(noises), 4 * len(counts)), squeeze=False)
for row, n in enumerate(counts):
    for col, noise in enumerate(noises):
        ax = axes[row][col]
        for x in protocols:
            ax.plot(ps, results[(noise, n)][x], "o-", label=x, markersize=3)
        ax.axhline(0.9, color="grey", lw=0.8, ls="--")
        ax.set_xscale("log", base=2)
        ax.set_ylim(0, 1.02)
        ax.set_xlabel("ranks")
        ax.set_ylabel("predicted parallel efficiency")
        ax.set_title("%s, %d chains per rank" % (noise, n), fontsize=10)
        ax.legend(fontsize=7)
fig.suptitle("relt round loop: cost model (waiting simulated from measured stepping times)")
fig.tight_layout()
fig.savefig(a.out_png, dpi=100)
if a.summary:
    at = ps.index(1024)
    with open(a.summary, "a") as f:
        for noise in noises:
            res = results[(noise, counts[0])]
            f.write("| %s | %.2f ms, %.0f %%, longest %.0f ms | %s | %.1f %% | %s | %s |\n" % (
                a.label, t_g0 * 1e3, 100 * sigma0 / t_g0, max(t.max() for t in traces) * 1e3,
                " / ".join("%.1f %%" % (100 * x) for x in measured_share), 100 * (1 - replay), noise,
                " | ".join("%.1f %%" % (100 * res[x][at]) for x in protocols)))
if a.length_summary:
    with open(a.length_summary, "a") as f:
        f.write("| %s | %.2f ms, %.0f %%, longest %.0f ms | %.0f s | %s |\n" % (
            a.label, t_g0 * 1e3, 100 * sigma0 / t_g0, max(t.max() for t in traces) * 1e3, seconds0, " | ".join(
                " / ".join("%.1f %%" % (100 * v) for v in lengths[x]) for x in lengths)))
print(open(a.out_md).read())
