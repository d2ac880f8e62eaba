"""Samples per second of a campaign on 1 and 2 local workers, and the per-shard rate that sizes
a large campaign (docs/campaign.md). Not a test: it prints what it measured.

    python py/bench/campaign_rates.py --sim model --shards 8 --per-shard 50000
    python py/bench/campaign_rates.py --sim /path/to/obj/pipe --shards 8 --per-shard 40000
"""

import argparse
import os
import statistics

from uvt.campaign import Campaign, run


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--sim", default="model")
    p.add_argument("--shards", type=int, default=8)
    p.add_argument("--per-shard", type=int, default=50_000)
    p.add_argument("--repeat", type=int, default=2)
    a = p.parse_args()
    spec = Campaign(shards=a.shards, per_shard=a.per_shard, simulator=a.sim)
    best = {}
    for w in (1, 2):
        for _ in range(a.repeat):
            s = run(spec, workers=w, progress=False)
            assert s.passed, s.table()
            shard_rate = statistics.median(r["records"] / r["seconds"] for r in s.shards.values())
            print(f"workers {w}: {s.records} records in {s.seconds:.2f} s = {s.rate:,.0f} /s; "
                  f"median shard {shard_rate:,.0f} /s; load average {os.getloadavg()[0]:.2f}")
            best[w] = max(best.get(w, 0), s.rate)
    print(f"best: 1 worker {best[1]:,.0f} /s, 2 workers {best[2]:,.0f} /s, "
          f"ratio {best[2] / best[1]:.2f}")


if __name__ == "__main__":
    main()
