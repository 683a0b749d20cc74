#!/usr/bin/env python3
"""Efficiency of `mpirun -np N rts render` at rank counts this machine lacks, SIMULATED by
replaying measured costs (docs/scale-out.md). Inputs: a --tile-log of a one-process render
(--threads 1: every tile's own cost) and one of an `mpirun -np 2` render of the same scene (rank
0's serial cost per tile gathered from another rank: answering the request, then receiving,
storing and journaling the result).

The model is rts's queue (dist/tile_exchange.cpp): every rank starts after the start-up measured
in the one-process run (each rank evaluates the scene and builds its BVH); rank 0 renders on a
thread of its own, taking tiles from the queue at no cost, while its main thread serves the
others one message at a time; a worker asks, waits for its answer, renders, returns the tile and
asks again. Rounds of a progressive render are barriers. Not modelled: network latency beyond
the measured loopback cost, mpirun's own start-up, and ranks of unequal speed.

  simulate.py ONE.jsonl NP2.jsonl [--ranks 1,2,8,64,256] [--speed 1,16]
--work w: every tile w times as dear (the same image at w times the samples).
--speed k: ranks k times as fast as one thread (k threads a rank, scaling perfectly): tiles cost
1/k, the root's service does not shrink, so the root saturates sooner.
"""
import argparse
import heapq
import json
from collections import defaultdict


def read_log(path):
    tiles, summary = [], None
    with open(path) as f:
        for line in f:
            rec = json.loads(line)
            if "summary" in rec:
                summary = rec["summary"]
            else:
                tiles.append(rec)
    if summary is None:
        raise SystemExit(f"{path}: no summary line (is it a --tile-log?)")
    return tiles, summary


def simulate(rounds, ranks, startup, serve, fold):
    """Wall time of the render phase plus start-up, for `ranks` ranks of equal speed."""
    t = startup
    for costs in rounds:  # costs: tile costs in queue order
        queue = list(costs)
        nxt = 0
        server_free = t
        # Events: (time, kind, rank). kind 0: a worker's request arrives; 1: its result arrives.
        events = [(t, 0, r) for r in range(1, ranks)]
        heapq.heapify(events)
        local_free = t  # rank 0's rendering thread
        end = t
        # Rank 0's thread takes tiles whenever it is free; interleave it with the server by time.
        while True:
            # Let rank 0's thread take a tile if it is free no later than the next event.
            next_event = events[0][0] if events else float("inf")
            if nxt < len(queue) and local_free <= next_event:
                local_free += queue[nxt]
                nxt += 1
                end = max(end, local_free)
                continue
            if not events:
                break
            time, kind, rank = heapq.heappop(events)
            start = max(time, server_free)
            if kind == 0:  # answer a request
                server_free = start + serve
                if nxt < len(queue):
                    done = server_free + queue[nxt]
                    nxt += 1
                    heapq.heappush(events, (done, 1, rank))
            else:  # fold a result; the worker asks again at once
                server_free = start + fold
                end = max(end, server_free)
                heapq.heappush(events, (time, 0, rank))
        t = max(end, local_free, server_free)
    return t


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("one")
    ap.add_argument("np2")
    ap.add_argument("--ranks", default="1,2,8,64,256")
    ap.add_argument("--speed", default="1,16")
    ap.add_argument("--work", type=float, default=1.0)
    a = ap.parse_args()
    tiles, s1 = read_log(a.one)
    _, s2 = read_log(a.np2)
    if s1["ranks"] != 1 or s1["threads"] != 1:
        raise SystemExit(f"{a.one}: needs a one-process, one-thread render (--threads 1, no mpirun)")
    if not s2["rendered_remote"]:
        raise SystemExit(f"{a.np2}: no tile came from another rank")
    serve = s2["serve_seconds"] / s2["rendered_remote"]
    fold = s2["fold_seconds"] / s2["rendered_remote"]
    startup = s1["eval_seconds"] + s1["build_seconds"]
    by_round = defaultdict(list)
    for rec in sorted(tiles, key=lambda r: r["unit"]):
        by_round[rec["round"]].append(rec["seconds"])
    rounds = [by_round[k] for k in sorted(by_round)]
    work = sum(sum(r) for r in rounds)
    print(f"# {len(tiles)} tiles in {len(rounds)} round(s), {work * a.work:.3f} s of one-thread rendering "
          f"(measured x {a.work:g}); "
          f"start-up {startup * 1e3:.1f} ms; root per remote tile: serve {serve * 1e6:.1f} us + fold {fold * 1e6:.1f} us")
    print("| rank speed | ranks | simulated wall (s) | speed-up | efficiency |")
    print("|---|---|---|---|---|")
    for k in [float(x) for x in a.speed.split(",")]:
        scaled = [[c * a.work / k for c in r] for r in rounds]
        one = simulate(scaled, 1, startup, serve, fold)
        for n in [int(x) for x in a.ranks.split(",")]:
            tn = simulate(scaled, n, startup, serve, fold)
            print(f"| {k:g}x | {n} | {tn:.3f} | {one / tn:.1f} | {one / tn / n:.2f} |")


if __name__ == "__main__":
    main()
