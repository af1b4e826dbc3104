"""Cost model of relt's round loop (docs/SCALING.md): predicted parallel efficiency against ranks.

python3 model.py STATS.json COLLECTIVES.jsonl OUT.md OUT.png [--alpha SECONDS] [--bandwidth BYTES_PER_S]
                [--chains-per-rank N ...]

STATS.json: a 2-rank relt render with spread placement (per-rank stepping time of a group round,
its spread, time deciding the exchanges); COLLECTIVES.jsonl: relt_bench_collectives on 2 ranks
(copy bandwidth of this machine). --alpha/--bandwidth: the cluster network's latency per
message step and bandwidth (defaults: 2 us, 12 GB/s, an InfiniBand EDR-class fabric).

Weak scaling in chains: every rank keeps N chains (default: as measured, and twice that), so the
stepping time of a group round t_g is the measured one scaled by N (its spread by sqrt N, the
sum of independent mutations); what grows with P is per protocol:
  blocking-spread   one blocking allgather of every chain's targets per round, every rank decides
                    every ladder's exchange, waits for the slowest of P ranks each round
  staggered-spread  (relt up to 8 ranks) the same messages and decisions, rounds of two ladder
                    groups half a round apart: network time hides behind the other group's work,
                    decisions and copying the gathered targets do not
  sub-communicators spread, but each ladder exchanges on its own communicator of M ranks: a rank
                    takes part in one small collective per hosted chain per round
  staggered-packed  (relt above 8 ranks) whole ladders per rank, decisions local, messages of
                    M + 3 numbers per rank
Waiting: blocking waits for the maximum of P per-round fluctuations, sigma_g sqrt(2 ln P).
Staggered rounds absorb a lag of up to one group round tau = t_g; the lag between two ranks is
then a random walk reflected at +-tau, which waits about sigma_g^2 / tau per group round; for P
ranks we scale this by ln P / ln 2. Homogeneous nodes after load balancing are assumed.
"""
import argparse
import json
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("stats")
ap.add_argument("collectives")
ap.add_argument("out_md")
ap.add_argument("out_png")
ap.add_argument("--alpha", type=float, default=2e-6)
ap.add_argument("--bandwidth", type=float, default=12e9)
ap.add_argument("--chains-per-rank", type=int, nargs="*")
a = ap.parse_args()

j = json.load(open(a.stats))
r = j["relt"]
s = j["settings"]
ranks0 = j["ranks"]
levels = len(r["levels"])
groups = r["groups"]
interval = s["exchange_interval"]
measured_chains = s["ladders"] * levels / ranks0
t_g0 = sum(r["group_round_step_seconds_mean_per_rank"]) / ranks0       # stepping a group round
sigma0 = sum(r["group_round_step_seconds_deviation_per_rank"]) / ranks0
t_ladder = sum(r["group_round_finish_seconds_mean_per_rank"]) / ranks0 / (s["ladders"] / groups)
coll = [json.loads(line) for line in open(a.collectives) if line.strip()]
big = max(coll, key=lambda c: c["doubles_per_rank"])
copy_bw = big["doubles_per_rank"] * 8 * big["ranks"] / big["allgatherv_seconds"]  # bytes/s, this machine
counts = a.chains_per_rank or [int(measured_chains), int(2 * measured_chains)]


def allgather(p, total_bytes):
    """Network time of an allgather (recursive doubling / ring): latency log2 P, all bytes once."""
    return a.alpha * math.ceil(math.log2(p)) + total_bytes / a.bandwidth if p > 1 else 0.0


def efficiency(protocol, p, chains_rank):
    scale = chains_rank / measured_chains
    t_g, sigma = t_g0 * scale, sigma0 * math.sqrt(scale)
    ladders_rank_group = chains_rank / levels / groups
    lnp = math.log(p) if p > 1 else 0.0
    if protocol == "blocking-spread":
        msg = p * (chains_rank * levels + levels + 3) * 8  # one round = both groups at once
        t = 2 * t_g
        over = 2 * p * ladders_rank_group * t_ladder + msg / copy_bw + allgather(p, msg)
        wait = sigma * math.sqrt(2) * math.sqrt(2 * lnp)
        return t / (t + over + wait)
    stag_wait = sigma ** 2 / t_g * (lnp / math.log(2)) if p > 1 else 0.0
    if protocol == "staggered-spread":
        msg = p * (chains_rank / groups * levels + levels + 3) * 8
        exposed = max(0.0, allgather(p, msg) - t_g)
        over = p * ladders_rank_group * t_ladder + msg / copy_bw + exposed
        return t_g / (t_g + over + stag_wait)
    if protocol == "sub-communicators":
        # chains of a rank belong to different ladders: one collective of M ranks per chain and round
        per = chains_rank / groups * (a.alpha * math.ceil(math.log2(levels)) + levels * levels * 8 / a.bandwidth) \
            if p > 1 else 0.0
        over = ladders_rank_group * t_ladder + per
        return t_g / (t_g + over + stag_wait)
    if protocol == "staggered-packed":
        msg = p * (levels + 3) * 8
        exposed = max(0.0, allgather(p, msg) - t_g)
        over = ladders_rank_group * t_ladder + msg / copy_bw + exposed
        return t_g / (t_g + over + stag_wait)
    raise ValueError(protocol)


protocols = ["blocking-spread", "staggered-spread", "sub-communicators", "staggered-packed"]
ps = [2 ** k for k in range(0, 13)]
with open(a.out_md, "w") as f:
    f.write("Measured inputs (2 ranks, %s, %d chains per rank, %d levels, interval %d): stepping a group "
            "round t_g = %.3f ms, its spread sigma_g = %.3f ms (%.1f %%), deciding one ladder's exchange "
            "%.2f us, this machine's copy bandwidth %.1f GB/s. Network: latency %.1f us per step, "
            "%.0f GB/s.\n" % (s["scene"].split("/")[-1], measured_chains, levels, interval, t_g0 * 1e3,
                              sigma0 * 1e3, 100 * sigma0 / t_g0, t_ladder * 1e6, copy_bw / 1e9,
                              a.alpha * 1e6, a.bandwidth / 1e9))
    for n in counts:
        f.write("\nPredicted efficiency, %d chains per rank:\n\n" % n)
        f.write("| ranks | " + " | ".join(protocols) + " |\n|---|" + "---|" * len(protocols) + "\n")
        for p in ps:
            f.write("| %d | " % p + " | ".join("%.1f %%" % (100 * efficiency(x, p, n)) for x in protocols) + " |\n")
fig, axes = plt.subplots(1, len(counts), figsize=(6 * len(counts), 4), squeeze=False)
for ax, n in zip(axes[0], counts):
    for x in protocols:
        ax.plot(ps, [efficiency(x, p, n) for p in ps], "o-", label=x, markersize=3)
    ax.axhline(0.9, color="grey", lw=0.8, ls="--")
    ax.set_xscale("log", base=2)
    ax.set_ylim(0, 1.02)
    ax.set_xlabel("ranks")
    ax.set_ylabel("predicted parallel efficiency")
    ax.set_title("%d chains per rank" % n)
    ax.legend(fontsize=8)
fig.suptitle("relt round loop: cost model")
fig.tight_layout()
fig.savefig(a.out_png, dpi=110)
print(open(a.out_md).read())
