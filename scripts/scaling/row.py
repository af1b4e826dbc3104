"""One CSV row of a scaling run from relt's stats.json: python3 row.py STATS EXPERIMENT CORES."""
import json
import sys

stats, experiment, cores = sys.argv[1], sys.argv[2], int(sys.argv[3])
j = json.load(open(stats))
r = j["relt"]
s = j["settings"]
loop = r["loop_seconds"]
coll = r["round_collective_seconds_per_rank"]
mean = r["group_round_step_seconds_mean_per_rank"]
dev = r["group_round_step_seconds_deviation_per_rank"]
cv = max(d / m for d, m in zip(dev, mean) if m > 0) if any(m > 0 for m in mean) else 0.0
print(",".join(str(x) for x in [
    experiment, j["ranks"], int(j["ranks"] > cores), s["exchange_interval"], r["placement"], s["ladders"],
    j["mutations"], round(loop, 4), round(max(coll) / loop, 5), round(sum(coll) / len(coll) / loop, 5),
    round(sum(mean) / len(mean), 7), round(cv, 4), r["chain_moves"]]))
