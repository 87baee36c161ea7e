"""cartan.sweep: many transported-velocity problems at once, on local threads, on any
concurrent.futures-style executor (processes, a cluster) or on a Dask distributed client.

Every problem is checked (its keys and argument types here, then the library's own validation,
``<Group>._validate`` or, for a manifold's problem, ``_validate_general``) before any work is
submitted; the problems then go out in chunks of
consecutive problems, one task per chunk, and the results come back in the problems' order.
The solver is deterministic, so the results are the same bit for bit wherever they were computed
(all fields but ``solve_time``).

Local threads give parallelism because a solve of a built-in model, or of a manifold's particle
given by its terms, runs without the GIL (python/src/python_models.hpp, visit_model;
python/src/general_binding.hpp, solve_on); a Lagrangian written in Python holds the GIL in its
callbacks, so its problems run one at a time on threads: use a ProcessPoolExecutor for those.
"""
import concurrent.futures
import inspect
import math
import numbers
import os
from collections.abc import Mapping

from ._arguments import check_types

#: Keyword arguments of cartan.solve a sweep does not take: a progress callable would have to
#: cross to the workers, and its calls from many solves at once would interleave.
_NOT_IN_SWEEPS = ("progress",)




#: The default number of tasks, at most (chunksize = ceil(len(problems) / _TASKS)).
_TASKS = 1000


def sweep(problems, executor=None, *, chunksize=None):
    """Solves every problem of `problems` with :func:`cartan.solve` and returns the
    :class:`cartan.Result` s in the same order.

    problems: a sequence of dicts of cartan.solve's keyword arguments, ``lagrangian`` included, e.g.
    ``[dict(lagrangian=cartan.RigidBody([2, 3, 4]), lam=lam, T=50, N=1000, gT=gT) for lam in lams]``
    or a manifold's, ``dict(lagrangian=cartan.Sphere(), T=T, N=200, q0=q0, qT=qT, gravity=9.81)``
    (every argument but ``progress``).
    executor: None (default) for a pool of os.cpu_count() local threads; or any
    concurrent.futures.Executor (``submit``; or an object with ``map`` only, which must keep the
    order as Executor.map does), e.g. a ProcessPoolExecutor; or a Dask ``distributed.Client``
    (``map`` with ``gather``). Across processes the problems and results are pickled: the built-in
    models pickle by their inertia, a Lagrangian written in Python must be picklable (a class at
    module level that the workers can import; Dask pickles with cloudpickle).
    chunksize: problems per task (default 1 for the local threads, else ceil(len(problems) / 1000),
    so that a sweep of 10^6 problems is 1000 tasks, not 10^6 scheduler entries).

    A problem that fails numerically gives a result with its status (success False), not an
    exception. A bad problem raises TypeError (not a dict, an unknown or missing key, a value of
    the wrong type) or ValueError (the library's check of the values) naming problems[i], before
    anything is solved. An exception raised while solving (e.g. in a Python callback) is re-raised
    with the index: a ValueError as "cartan.sweep: problems[i]: ...", any other unchanged with a note.
    """
    from . import solve

    problems = list(problems)
    signature = inspect.signature(solve)
    checked = [_checked(i, problem, signature) for i, problem in enumerate(problems)]
    if chunksize is None:
        chunksize = 1 if executor is None else max(1, math.ceil(len(problems) / _TASKS))
    if not isinstance(chunksize, numbers.Integral) or isinstance(chunksize, bool) or chunksize < 1:
        raise ValueError(f"cartan.sweep: chunksize = {chunksize!r} must be a positive integer")
    starts = list(range(0, len(checked), chunksize))
    chunks = [checked[s:s + chunksize] for s in starts]
    if not chunks:
        return []
    if executor is None:
        return _flatten(_run_on_threads(starts, chunks))
    return _flatten(_run(executor, starts, chunks))


def _run_on_threads(starts, chunks):
    """The chunks on a pool of local threads. Ctrl-C reaches the main thread only: it cancels the
    chunks not started and the solves still running (a cancel token, which their monitors poll:
    they stop at their next iteration, in the background) and raises KeyboardInterrupt at once,
    without waiting for them."""
    from ._cartan import _CancelToken

    token = _CancelToken()

    def task(start, chunk):
        with token:
            return solve_chunk(start, chunk)

    pool = concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1)
    try:
        futures = [pool.submit(task, s, c) for s, c in zip(starts, chunks)]
        results = [f.result() for f in futures]
    except BaseException:
        token.cancel()
        pool.shutdown(wait=False, cancel_futures=True)
        raise
    pool.shutdown()
    return results


def solve_chunk(start, problems):
    """Solves problems[0], problems[1], ... (problems[start], ... of the sweep) in turn: the task
    a worker runs. Errors are re-raised naming the sweep's index (see :func:`sweep`)."""
    from . import solve

    results = []
    for k, problem in enumerate(problems):
        try:
            results.append(solve(**problem))
        except ValueError as e:
            raise ValueError(f"cartan.sweep: problems[{start + k}]: {e}") from e
        except Exception as e:
            e.add_note(f"cartan.sweep: raised while solving problems[{start + k}]")
            raise
    return results


def _run(executor, starts, chunks):
    """The chunks' lists of results, in order, from a Dask client, an Executor or a map."""
    if hasattr(executor, "gather") and hasattr(executor, "map"):  # distributed.Client
        return executor.gather(executor.map(solve_chunk, starts, chunks, pure=False))
    if hasattr(executor, "submit"):
        futures = [executor.submit(solve_chunk, s, c) for s, c in zip(starts, chunks)]
        try:
            return [f.result() for f in futures]
        except BaseException:
            for f in futures:
                f.cancel()
            raise
    if hasattr(executor, "map"):
        return list(executor.map(solve_chunk, starts, chunks))
    raise TypeError(f"cartan.sweep: executor = {executor!r} has neither submit nor map "
                    "(give a concurrent.futures.Executor, a distributed.Client, or None for local threads)")


def _flatten(lists):
    return [result for results in lists for result in results]


def _checked(i, problem, signature):
    """The problem as a plain dict of all of cartan.solve's arguments (defaults filled in), after
    the checks of :func:`sweep`."""
    where = f"cartan.sweep: problems[{i}]"
    if not isinstance(problem, Mapping):
        raise TypeError(f"{where} = {type(problem).__name__} is not a dict of cartan.solve's keyword arguments")
    excluded = _NOT_IN_SWEEPS
    for key in problem:
        if key not in signature.parameters or key in excluded:
            takes = ", ".join(k for k in signature.parameters if k not in excluded)
            raise TypeError(f"{where}: key {key!r} is not an argument of a sweep's problem (one of: {takes})")
    try:
        bound = signature.bind(**problem)
    except TypeError as e:  # "missing a required argument: 'T'"
        raise TypeError(f"{where}: {e}") from None
    check_types(where, problem)
    bound.apply_defaults()
    arguments = dict(bound.arguments)
    from . import MANIFOLDS, _solve_on_manifold, _transported

    lagrangian, space = arguments.get("lagrangian"), arguments.get("space")
    try:
        if space is not None or isinstance(lagrangian, MANIFOLDS):  # a manifold's problem (as cartan.solve)
            manifold = space if space is not None else lagrangian
            _solve_on_manifold(manifold, None if lagrangian is manifold else lagrangian, arguments, validate=True)
        else:
            _transported("_validate", arguments)
    except ValueError as e:
        raise ValueError(f"{where}: {e}") from e
    except TypeError as e:  # a group model's required lam or gT
        raise TypeError(f"{where}: {e.args[0].removeprefix('cartan.solve: ')}") from None
    return {key: value for key, value in arguments.items() if key in problem}
