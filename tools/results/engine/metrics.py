"""Reading what runs wrote: compare's and animate's metrics.json, bench's bench.json, converge's
convergence.json, prefilter's JSON, and each run's record (its standard output and seconds). Methods are found by the name
glintlab gives them: an id, or a variant's name ("podee{area=lens}")."""

import json

from .errors import InputError


class Outputs:
    def __init__(self, runs, out_dir, runner):
        self.runs = runs          # id -> engine.runs.Run
        self.out_dir = out_dir
        self.runner = runner
        self._json = {}

    def run(self, run_id):
        if run_id not in self.runs:
            near = sorted(r for r in self.runs if r.split("/")[0] == run_id.split("/")[0])[:8]
            raise InputError(f"no run '{run_id}'" + (f"; runs near it: {', '.join(near)}" if near else
                                                     "; runs are named by their id in the experiment files"))
        return self.runs[run_id]

    def metrics(self, run_id):
        """The JSON a run wrote: metrics.json, bench.json or prefilter's file."""
        run = self.run(run_id)
        files = {"compare": "metrics.json", "animate": "metrics.json", "bench": "bench.json",
                 "converge": "convergence.json"}
        if run.command in files:
            path = self.out_dir / run_id / files[run.command]
        elif run.command == "prefilter":
            path = self.out_dir / f"{run_id}.json"
        else:
            raise InputError(f"run '{run_id}' is a {run.command} run: it writes no metrics (read its stdout)")
        if path not in self._json:
            try:
                self._json[path] = json.loads(path.read_text())
            except FileNotFoundError:
                raise InputError(f"{path}: missing (run '{run_id}' has not run)") from None
        return self._json[path]

    def field(self, run_id, key):
        j = self.metrics(run_id)
        if key not in j:
            raise InputError(f"run '{run_id}' has no '{key}'; it has: {', '.join(sorted(j))}")
        return j[key]

    def entry(self, run_id, method):
        """A method's entry in methods[] of a run's metrics."""
        entries = self.field(run_id, "methods")
        for e in entries:
            if e["method"] == method:
                return e
        raise InputError(f"run '{run_id}' has no method '{method}'; it has: {', '.join(e['method'] for e in entries)}")

    def metric(self, run_id, method, key):
        e = self.entry(run_id, method)
        if key not in e:
            raise InputError(f"method '{method}' of run '{run_id}' has no '{key}'; it has: {', '.join(sorted(e))}")
        return e[key]

    def methods(self, run_id):
        return [e["method"] for e in self.field(run_id, "methods")]

    def file_of(self, run_id, method):
        """The file name of a method's images: its 'file', or (outputs before variants) its name."""
        return self.entry(run_id, method).get("file", method)

    def record(self, run_id):
        self.run(run_id)
        r = self.runner.record(run_id)
        if r is None:
            raise InputError(f"run '{run_id}' has no record (it has not run)")
        return r
