"""Many viewpoints of one scene on a Dask cluster.

The scene is read once and scattered to the workers; each task runs a chunk
of the jobs with ``genbsp.batch`` (on one thread: Dask gives each worker its
share of the cores), and the results come back in job order.  Files the jobs
write (maps, images) go to their paths, which on a real cluster should be on
shared storage.

Run it on a local cluster of two worker processes:

    python3 examples/python/dask_batch.py SCENE.off EYES.txt [--scheduler ADDRESS]

where EYES.txt has one ``x y z`` per line; with ``--scheduler`` it uses a
running cluster (``dask-scheduler`` and ``dask-worker`` on several machines;
docs/batch.md).  It prints one JSON line per job.
"""

from __future__ import annotations

import argparse
import json
import sys
from typing import Any, Sequence

import genbsp


def run_chunk(scene: genbsp.Scene, jobs: Sequence[dict[str, Any]], first: int) -> list[dict[str, Any]]:
    """One task: a chunk of jobs on one thread; job numbers made global."""
    results = genbsp.batch(scene, jobs, workers=1).jobs
    for r in results:
        r["job"] += first
    return results


def batch_on_cluster(client: Any, scene: genbsp.Scene, jobs: Sequence[dict[str, Any]], chunk: int = 4) -> list[dict[str, Any]]:
    """Runs ``jobs`` on the cluster behind ``client``: the scene scattered
    once, one task per ``chunk`` jobs; the results in job order."""
    [shared] = client.scatter([scene], broadcast=True)
    futures = [client.submit(run_chunk, shared, list(jobs[i : i + chunk]), i, pure=False) for i in range(0, len(jobs), chunk)]
    results = [r for part in client.gather(futures) for r in part]
    return sorted(results, key=lambda r: r["job"])


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene")
    parser.add_argument("eyes", help="one 'x y z' per line (read exactly)")
    parser.add_argument("--scheduler", help="address of a running Dask scheduler (default: a local cluster of 2 workers)")
    parser.add_argument("--workers", type=int, default=2)
    args = parser.parse_args(argv)

    from dask.distributed import Client, LocalCluster

    scene = genbsp.Scene.from_file(args.scene)
    jobs = [{"eye": line.split(), "stats": True} for line in open(args.eyes) if line.strip() and not line.startswith("#")]
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        client = Client(LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, dashboard_address=None))
    with client:
        for r in batch_on_cluster(client, scene, jobs):
            print(json.dumps(r))
    return 0


if __name__ == "__main__":
    sys.exit(main())
