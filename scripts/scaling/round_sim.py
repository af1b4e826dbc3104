"""Replays stepping times through relt's round protocols (used by model.py, tested by
test_round_sim.py).

A trace is one rank's stepping time of each group round in loop order (group = index mod G), as
relt writes it with --trace FILE (group_round_step_seconds_per_rank). The simulation follows
src/replica/round_loop.cpp: a rank steps group g of round R once group g's collective of round
R - 1 has completed, and that collective completes when the last rank has posted it (plus a
latency). Blocking is the design's original protocol: all groups, then one collective that every
rank waits for. The result is the parallel efficiency: stepping time over ranks x makespan.
"""
import numpy as np


def staggered(traces, groups, latency=0.0, lag=1):
    """traces: array (ranks, group rounds). Efficiency of the staggered loop with `groups` groups.
    lag > 1: group g of round R waits only for its collective of round R - lag (relt's
    --normaliser-lag: normalisers applied `lag` rounds late, decisions local). lag may also be a
    function of the round R (a lag that grows with the render)."""
    traces = np.asarray(traces, dtype=float)
    ranks, n = traces.shape
    free = np.zeros(ranks)  # when each rank finishes its current work
    done = np.zeros(n)      # when the collective posted after group round i completed on every rank
    for i in range(n):
        before = i - (lag(i // groups) if callable(lag) else lag) * groups  # the same group, `lag` rounds earlier
        free = (np.maximum(free, done[before]) if before >= 0 else free) + traces[:, i]
        done[i] = free.max() + latency
    return traces.sum() / (ranks * free.max())


def blocking(traces, groups, latency=0.0):
    """One blocking collective per round after all `groups` group rounds."""
    traces = np.asarray(traces, dtype=float)
    ranks, n = traces.shape
    rounds = n // groups
    per_round = traces[:, : rounds * groups].reshape(ranks, rounds, groups).sum(axis=2)
    makespan = (per_round.max(axis=0) + latency).sum()
    return per_round.sum() / (ranks * makespan)


def bootstrap(traces, ranks, groups, block, rng, copies=1, length=None):
    """Traces for `ranks` ranks from measured ones: each is a run of blocks of `block` group rounds
    (a multiple of `groups`, so a block keeps its group order and its slow drifts) cut at random
    places of randomly chosen measured ranks, each measured trace first scaled to the common mean
    (homogeneous nodes: persistent speed differences are what load balancing removes). With
    copies = k, each group round is the sum of k such runs: k times the chains per rank, their
    fluctuations independent. length: group rounds per rank (default: the measured traces', cut
    to whole blocks); a multiple of the measured length models a longer render, its blocks
    independent of each other (phases of this VM that outlast a block are not in it)."""
    measured = [np.asarray(t, dtype=float) for t in traces]
    mean = np.mean([t.mean() for t in measured])
    measured = [t * (mean / t.mean()) for t in measured]
    n = min(len(t) for t in measured) // block * block
    if n == 0:
        raise ValueError("traces shorter than one block")
    blocks = np.stack([t[s:s + block] for t in measured for s in range(0, len(t) - block + 1, groups)])
    n = n if length is None else max(block, int(length) // block * block)
    out = np.zeros((ranks, n))
    for _ in range(copies):
        picks = rng.integers(0, len(blocks), size=(ranks, n // block))
        out += blocks[picks].reshape(ranks, n)
    return out
