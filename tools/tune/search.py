"""The search: an optuna study driven through its ask/tell interface, each
trial's rollouts dispatched as Ray tasks (strider-sim in a subprocess), at
most `workers` of them at once, with a progress bar showing the best so far.

The model's own parameters (the defaults) are walked first, exactly, as the
baseline; the study's first trial is the defaults on the search grid."""
import os
import pathlib
import time

import optuna
import ray
from tqdm import tqdm

import objectives
import space

HERE = pathlib.Path(__file__).resolve().parent


@ray.remote(num_cpus=1)
def rollout_task(sim, robot, gait, params, defaults, spec):
    r = objectives.walk_run(sim, robot, gait, params, defaults, spec)
    r.pop("log", None)  # the replies stay on the worker: the measures are what the driver needs
    return r


def start_ray(workers, address=None):
    """A new Ray instance on this machine with `workers` CPUs (never one that
    is already running here), or the cluster at `address`. Workers import
    tools/tune and tools/sim from the same path as here: on a cluster every
    node needs this checkout, built, at this path."""
    env = {"env_vars": {"PYTHONPATH": os.pathsep.join([str(HERE), str(HERE.parent / "sim")])}}
    if address:
        ray.init(address=address, runtime_env=env, log_to_driver=False)
    else:
        ray.init(address="local", num_cpus=workers, include_dashboard=False, runtime_env=env, log_to_driver=False)
    return ray.cluster_resources()


def make_sampler(name, seed):
    if name == "cmaes":  # the swing shape is categorical: CMA-ES samples it independently
        return optuna.samplers.CmaEsSampler(seed=seed, warn_independent_sampling=False)
    # constant_liar: trials still walking count as bad guesses, so parallel asks spread out.
    return optuna.samplers.TPESampler(seed=seed, multivariate=True, n_startup_trials=8, constant_liar=True)


def distributions(search_space):
    out = {}
    for key, r in search_space.items():
        if isinstance(r[0], str):
            out[key] = optuna.distributions.CategoricalDistribution(list(r))
        else:
            out[key] = optuna.distributions.FloatDistribution(r[0], r[1], step=r[2])
    return out


class Search:
    def __init__(self, sim, robot, gait, objective, defaults, search_space, sampler="tpe", seed=1, lift_ms=0.0):
        self.sim, self.robot, self.gait, self.objective = str(sim), robot, gait, objective
        self.lift_ms = lift_ms  # the servos' lift: the shortest cycle of a duty (space.complete)
        self.defaults, self.space = defaults, search_space
        self.dists = distributions(search_space)
        optuna.logging.set_verbosity(optuna.logging.WARNING)
        self.study = optuna.create_study(direction=objective.direction, sampler=make_sampler(sampler, seed))
        self.study.enqueue_trial(space.snapped(defaults, search_space))
        self.baseline = None
        self.records = []
        self.rollouts = 0
        self.rollout_s = 0.0

    def _finish(self, job):
        results = job["results"]
        terms = self.objective.term_values(results)
        value = self.objective.value(terms)
        rec = {"trial": job["name"], "params": job["params"], "value": value, "terms": terms,
               "failed": sorted({r["why"] for r in results if r["failed"]}), "runs": results}
        if job["trial"] is None:
            self.baseline = rec
        else:
            self.study.tell(job["trial"], value)
            self.records.append(rec)
            self.records.sort(key=lambda r: int(r["trial"]))  # they finish in any order
        return rec

    def best(self):
        """The best trial's record (the earliest of equals), or None."""
        best = None
        for rec in self.records:
            if best is None or self.objective.better(rec["value"], best["value"]):
                best = rec
        return best

    def run(self, trials, workers, progress=True):
        specs = self.objective.runs()
        jobs, queue, in_flight = {}, [], {}
        baseline = {"name": "defaults", "trial": None, "params": dict(self.defaults),
                    "results": [None] * len(specs), "left": len(specs)}
        jobs["defaults"] = baseline
        queue += [("defaults", i) for i in range(len(specs))]
        asked = 0
        bar = tqdm(total=trials, desc=f"{self.robot} {self.gait} {self.objective.name}", unit="trial",
                   disable=not progress, dynamic_ncols=True)
        t0 = time.monotonic()
        while queue or in_flight or asked < trials:
            while len(in_flight) < workers and (queue or asked < trials):
                if not queue:
                    trial = self.study.ask(self.dists)
                    name = f"{trial.number}"
                    params = space.complete(trial.params, self.defaults, self.lift_ms)
                    jobs[name] = {"name": name, "trial": trial, "params": params,
                                  "results": [None] * len(specs), "left": len(specs)}
                    queue += [(name, i) for i in range(len(specs))]
                    asked += 1
                name, i = queue.pop(0)
                job = jobs[name]
                ref = rollout_task.remote(self.sim, self.robot, self.gait, job["params"], self.defaults, specs[i])
                in_flight[ref] = (name, i)
            done, _ = ray.wait(list(in_flight), num_returns=1)
            for ref in done:
                name, i = in_flight.pop(ref)
                job = jobs[name]
                try:
                    job["results"][i] = ray.get(ref)
                except (ray.exceptions.RayError, OSError) as e:  # a worker lost, strider-sim hung
                    job["results"][i] = {"spec": specs[i], "failed": True, "why": f"rollout failed: {e}"[:200]}
                self.rollouts += 1
                job["left"] -= 1
                if job["left"] == 0:
                    self._finish(jobs.pop(name))
                    if name != "defaults":
                        bar.update(1)
                    b = self.best()
                    post = {}
                    if b is not None:
                        post["best"] = f"{b['value']:.4g} (#{b['trial']})"
                    if self.baseline is not None:
                        post["defaults"] = f"{self.baseline['value']:.4g}"
                    bar.set_postfix(post)
        self.rollout_s = time.monotonic() - t0
        bar.close()
        return self.best()
