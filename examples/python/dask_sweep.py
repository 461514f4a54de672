"""A sweep spread over Dask workers (docs/python.md: Spreading a sweep).

Starts a LocalCluster on the loopback (WORKERS processes of one thread
each, no dashboard) unless --scheduler names a running one, sweeps the
README's grid on the paper's board through cdvp.sweep(executor=client) in
tasks of --block points, prints each task's progress, the outcome and the
time taken, then calls it again (nothing left to run).

  PYTHONPATH=build/sw/python /usr/bin/python3 examples/python/dask_sweep.py --out results/dask
"""

import argparse
import time

import distributed

import cdvp


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True, help="the sweep's directory")
    parser.add_argument("--scheduler", help="a running Dask scheduler's address (tcp://HOST:PORT)")
    parser.add_argument("--workers", type=int, default=2, help="workers of a LocalCluster (default 2)")
    parser.add_argument("--block", type=int, default=4, help="points a task (default 4)")
    args = parser.parse_args()

    grid = {"m": [1, 2, 4, 8, 16, 24], "objects": "50:1600:x2"}
    points = {"board": "adm-xrc-ii", "scene": "spheres", "frames": 30, "baseline": "sap"}
    if args.scheduler:
        cluster = None
        client = distributed.Client(args.scheduler)
    else:
        cluster = distributed.LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                                           host="127.0.0.1", dashboard_address=None)
        client = distributed.Client(cluster)
    with client:
        print(f"workers: {len(client.scheduler_info()['workers'])}, block: {args.block}")
        started = time.monotonic()
        table = cdvp.sweep(grid, args.out, executor=client, block=args.block,
                           progress=lambda done, total: print(f"  {done}/{total} points"), **points)
        print(f"{time.monotonic() - started:.1f} s:", table.attrs["outcome"])
        print(table[["point", "status", "mean_total_ns", "sap_speedup"]].head(8).to_string(index=False))
        again = cdvp.sweep(grid, args.out, executor=client, block=args.block, **points)
        print("again:", again.attrs["outcome"])
    if cluster is not None:
        cluster.close()


if __name__ == "__main__":
    main()
