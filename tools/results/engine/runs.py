"""From [[run]] tables to command lines: the `for` matrix expanded, every string rendered as a
template, the glintlab flags built from the keys, and the quick mode's reductions applied.

A run's outputs live under the output folder (out/results) by its id:
    compare, animate, render   <out>/<id>/            (metrics.json, images, videos)
    converge                   <out>/<id>/            (convergence.json, .csv, .svg, the truth)
    bench                      <out>/<id>/bench.json
    prefilter                  <out>/<id>.json
    glintlab, tool             their standard output only
"""

import itertools
from dataclasses import dataclass, field

from .errors import InputError
from .template import render

# The flags of the keys that map one to one onto glintlab's own (docs: `glintlab compare --help`).
_FLAGS = [("spp", "--spp"), ("width", "--width"), ("height", "--height"), ("frames", "--frames"),
          ("frame", "--frame"), ("bench_frames", "--bench-frames"), ("warmup", "--warmup"),
          ("reference_backend", "--reference-backend"), ("reference_filter", "--reference-filter"),
          ("accuracy", "--accuracy"), ("max_depth", "--max-depth"), ("light_samples", "--light-samples")]
_INTEGER_KEYS = {"spp", "width", "height", "frames", "frame", "bench_frames", "warmup", "reference", "accuracy",
                 "max_depth", "light_samples"}
# Which keys each command takes (besides id, for, command).
_COMMAND_KEYS = {
    "compare": {"scene", "methods", "params", "spp", "width", "height", "frames", "frame", "reference_backend",
                "reference_filter", "no_cache", "args"},
    "animate": {"scene", "methods", "params", "spp", "width", "height", "frames", "reference_backend",
                "reference_filter", "no_cache", "args"},
    "bench": {"scene", "methods", "params", "width", "height", "frames", "bench_frames", "warmup", "args"},
    "render": {"scene", "methods", "params", "width", "height", "frame", "reference", "no_cache", "args"},
    "prefilter": {"scene", "params", "accuracy", "no_cache", "args"},
    "converge": {"scene", "params", "spp", "width", "height", "frame", "reference_backend", "max_depth",
                 "light_samples", "backends", "steps", "no_cache", "args"},
    "glintlab": {"args"},
    "tool": {"program", "args", "quick_args"},
}


@dataclass
class Run:
    id: str
    command: str
    where: str                    # "experiments/aa.toml: run[2]", for errors
    section: str                  # its section's name, or "" for a global run
    values: dict                  # the keys, rendered
    scene: str = ""               # as given: a declared scene's name, builtin:NAME or a path
    bindings: dict = field(default_factory=dict)  # the names its templates saw (a declared scene's too)


def _bindings(loops, scope, at):
    """The names of each run a `for` makes: a table of arrays (every combination, its keys the
    names), an array of tables (one run each), or the name of a [vars] array of tables."""
    if isinstance(loops, str):
        if not isinstance(scope.get(loops), list):
            raise InputError(f"{at}: for = '{loops}' names no [vars] array")
        loops = scope[loops]
    if isinstance(loops, list):
        if not all(isinstance(t, dict) for t in loops):
            raise InputError(f"{at}: for is {loops!r}; allowed: an array of tables, a table of arrays, or the name "
                             "of a [vars] array of tables")
        return loops
    names, lists = [], []
    for name, values in loops.items():
        if isinstance(values, str):
            if not isinstance(scope.get(values), list):
                raise InputError(f"{at}: for.{name} = '{values}' names no [vars] array")
            values = scope[values]
        names.append(name)
        lists.append(values)
    return [dict(zip(names, combination)) for combination in itertools.product(*lists)]


def expand(raw_runs, where, section, scope):
    """The runs of `raw_runs` (the [[run]] tables of one file), one per binding of each `for`."""
    runs = []
    for i, raw in enumerate(raw_runs):
        at = f"{where}: run[{i}]"
        allowed = _COMMAND_KEYS[raw["command"]] | {"id", "for", "command"}
        for key in raw:
            if key not in allowed:
                raise InputError(f"{at}: key '{key}' is not one of command '{raw['command']}'; allowed: "
                                 f"{', '.join(sorted(allowed))}")
        for names in _bindings(raw.get("for", {}), scope, at):
            bound = dict(scope, **names)
            values = {k: _rendered(v, bound, f"{at}.{k}") for k, v in raw.items() if k != "for"}
            for key in _INTEGER_KEYS & values.keys():
                values[key] = _integer(values[key], f"{at}.{key}", key == "spp")
            runs.append(Run(values["id"], raw["command"], at, section, values, values.get("scene", ""), bound))
    return runs


def _rendered(value, scope, where):
    if isinstance(value, str):
        return render(value, scope, where)
    if isinstance(value, list):
        return [_rendered(v, scope, f"{where}[{i}]") for i, v in enumerate(value)]
    return value


def _integer(value, where, auto_allowed):
    if isinstance(value, int) or (auto_allowed and value == "auto"):
        return value
    try:
        return int(value)
    except ValueError:
        raise InputError(f"{where} is '{value}'; allowed: an integer" + (" or auto" if auto_allowed else "")) from None


def quick(values, command):
    """The reductions of the quick mode (--quick, GLINTLAB_RESULTS_QUICK=1): a check of the program
    itself, never numbers to publish. The same rules as the former tools/make-results.sh's."""
    v = dict(values)
    for key in ("spp", "reference"):
        if isinstance(v.get(key), int):
            v[key] = max(4, v[key] // 64)
    for key in ("width", "height"):
        if key in v:
            v[key] = max(16, v[key] // 4)
    if "frames" in v:
        v["frames"] = min(v["frames"], 3)
    elif command == "animate":
        v["frames"] = 3
    if "bench_frames" in v:
        v["bench_frames"] = min(v["bench_frames"], 2)
    if "steps" in v:
        v["steps"] = v["steps"][:2]
    if "accuracy" in v:
        v["accuracy"] = min(v["accuracy"], 1)
    if command == "tool" and "quick_args" in v:
        v["args"] = v["quick_args"]
    return v


def command_line(run, scene_path, output, glintlab, is_quick):
    """glintlab's arguments (or the tool's whole command line) for `run`; `scene_path` is where its
    scene is (a generated file, builtin:NAME or a path) and `output` where its outputs go."""
    v = quick(run.values, run.command) if is_quick else run.values
    c = run.command
    if c == "tool":
        return [v["program"], *v.get("args", [])]
    if c == "glintlab":
        return [glintlab, *v.get("args", [])]
    argv = [glintlab, c]
    if c != "prefilter":
        argv.append("-q")
    if scene_path:
        argv += ["--scene", scene_path]
    if "methods" in v:
        methods = v["methods"] if isinstance(v["methods"], str) else ",".join(v["methods"])
        argv += ["--method" if c == "render" else "--methods", methods]
    for p in v.get("params", []):
        argv += ["--param", p]
    for key, flag in _FLAGS:
        if key in v:
            argv += [flag, str(v[key])]
    if "reference" in v:
        argv.append(f"--reference={v['reference']}")
    if "backends" in v:
        argv += ["--backends", v["backends"] if isinstance(v["backends"], str) else ",".join(v["backends"])]
    if "steps" in v:
        argv += ["--steps", ",".join(str(n) for n in v["steps"])]
    if v.get("no_cache"):
        argv.append("--no-cache")
    argv += v.get("args", [])
    return argv + ["-o", str(output)]


def output_of(run, out_dir):
    """Where a run's outputs go (None: it has only its standard output)."""
    if run.command in ("compare", "animate", "bench", "render", "converge"):
        return out_dir / run.id
    if run.command == "prefilter":
        return out_dir / f"{run.id}.json"
    return None
