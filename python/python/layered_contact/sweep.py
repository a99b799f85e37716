"""Parameter sweeps on a Dask cluster: scenes are independent, so each is
one task.

On one machine::

    from dask.distributed import Client, LocalCluster
    from layered_contact.sweep import run_scenes

    with LocalCluster(n_workers=2, threads_per_worker=1) as cluster, Client(cluster) as client:
        results = run_scenes(client, scenes)

On a Slurm cluster the same code runs with a ``dask_jobqueue.SLURMCluster``
in place of the ``LocalCluster`` (``cluster.scale(jobs=10)``); every worker
needs this package installed. Each worker runs one scene at a time on all
the cores it is given (set ``threads_per_worker=1`` and give each worker a
whole node or its share of cores through the job's CPU count:
the solver parallelises inside a scene with the Rayon thread pool, sized by
``RAYON_NUM_THREADS``).
"""

from __future__ import annotations

from typing import Any, Iterable, List

from . import SceneLike, curve_to_dict, run_scene


def run_one(scene: SceneLike) -> dict:
    """Runs one scene; its curve as plain values (see ``curve_to_dict``)."""
    return curve_to_dict(run_scene(scene))


def run_scenes(client: Any, scenes: Iterable[SceneLike]) -> List[dict]:
    """Runs ``scenes`` on the ``dask.distributed`` ``client``, one task each,
    and returns their curves (as ``curve_to_dict``) in the order given.
    A scene's error is raised here, with the library's message."""
    futures = client.map(run_one, list(scenes), pure=False)
    return client.gather(futures)
