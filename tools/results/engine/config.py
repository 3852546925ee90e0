"""Reading the program's TOML: tools/results/results.toml (the sections, in order, and what every
section shares) and tools/results/experiments/<section>.toml (a section's runs, scenes and lists).
Every key is checked: an unknown key, a wrong type or a missing value is an InputError naming the
file, the key, the value and what is allowed."""

import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from .errors import InputError

# The keys of a [[run]] and the type each takes (str keys may hold {{ }} templates).
RUN_KEYS = {
    "id": str, "for": (dict, list, str), "command": str, "scene": str, "methods": (str, list), "params": list,
    "spp": (int, str), "width": (int, str), "height": (int, str), "frames": (int, str), "frame": (int, str),
    "bench_frames": (int, str), "warmup": (int, str), "reference": (int, str), "reference_backend": str,
    "reference_filter": str, "accuracy": (int, str), "no_cache": bool, "args": list, "program": str,
    "quick_args": list, "max_depth": (int, str), "light_samples": (int, str), "backends": (str, list),
    "steps": list,
}
COMMANDS = ("compare", "animate", "bench", "render", "prefilter", "converge", "glintlab", "tool")
SCENE_KEYS = {"template": (str, list), "builtin": str, "replace": list, "transform": str, "file": str}
SPLICE_KEYS = {"file": str, "marker": str, "template": str}
SECTION_KEYS = {"template": str, "vars": dict, "scenes": dict, "run": list, "splice": list}
INDEX_KEYS = {"output": str, "images": str, "out": str, "build_dir": str, "build_targets": list, "header": str,
              "sections": list, "run": list, "report": dict, "vars": dict}
REPORT_KEYS = {"headline": str, "headline_runs": list}


@dataclass
class Section:
    name: str
    source: Path            # its experiment file
    template: str           # under templates/
    vars: dict
    scenes: dict            # name -> scene table
    runs: list              # raw [[run]] tables (expanded by engine/runs.py)
    splices: list = field(default_factory=list)


@dataclass
class Index:
    source: Path
    output: str
    images: str
    out: str
    build_dir: str
    build_targets: list
    header: str
    section_names: list
    runs: list              # global runs, shared by every section
    vars: dict
    report_headline: str
    report_runs: list


def _type_name(allowed):
    names = {str: "a string", int: "an integer", bool: "true or false", list: "an array", dict: "a table"}  # TOML's
    kinds = allowed if isinstance(allowed, tuple) else (allowed,)
    return " or ".join(names[k] for k in kinds)


def check_table(table, keys, where, required=()):
    """Every key of `table` known and of its type; the `required` ones present."""
    if not isinstance(table, dict):
        raise InputError(f"{where}: is {table!r}; allowed: a table")
    for key, value in table.items():
        if key not in keys:
            raise InputError(f"{where}: unknown key '{key}'; allowed: {', '.join(keys)}")
        allowed = keys[key]
        kinds = allowed if isinstance(allowed, tuple) else (allowed,)
        if not isinstance(value, kinds) or (isinstance(value, bool) and bool not in kinds):
            raise InputError(f"{where}: key '{key}' is {value!r}; allowed: {_type_name(allowed)}")
    for key in required:
        if key not in table:
            raise InputError(f"{where}: key '{key}' is missing")


def read_toml(path):
    try:
        with open(path, "rb") as f:
            return tomllib.load(f)
    except FileNotFoundError:
        raise InputError(f"{path}: does not exist") from None
    except tomllib.TOMLDecodeError as e:
        raise InputError(f"{path}: not valid TOML ({e})") from None


def _check_runs(runs, where):
    for i, run in enumerate(runs):
        at = f"{where}: run[{i}]"
        check_table(run, RUN_KEYS, at, required=("id", "command"))
        if run["command"] not in COMMANDS:
            raise InputError(f"{at}: command '{run['command']}'; allowed: {', '.join(COMMANDS)}")
        loops = run.get("for", {})
        for key, values in (loops.items() if isinstance(loops, dict) else []):
            if not isinstance(values, (list, str)):
                raise InputError(f"{at}: for.{key} is {values!r}; allowed: an array, or the name of a [vars] array")


def read_index(root):
    """tools/results/results.toml."""
    path = root / "results.toml"
    t = read_toml(path)
    check_table(t, INDEX_KEYS, str(path), required=("output", "images", "out", "build_dir", "header", "sections"))
    report = t.get("report", {})
    check_table(report, REPORT_KEYS, f"{path}: [report]")
    runs = t.get("run", [])
    _check_runs(runs, str(path))
    return Index(path, t["output"], t["images"], t["out"], t["build_dir"], t.get("build_targets", []), t["header"],
                 t["sections"], runs, t.get("vars", {}), report.get("headline", ""), report.get("headline_runs", []))


def read_section(root, name):
    """tools/results/experiments/<name>.toml."""
    path = root / "experiments" / f"{name}.toml"
    t = read_toml(path)
    check_table(t, SECTION_KEYS, str(path))
    for scene, table in t.get("scenes", {}).items():
        check_table(table, SCENE_KEYS, f"{path}: [scenes.{scene}]")
        if ("template" in table) == ("builtin" in table):
            raise InputError(f"{path}: [scenes.{scene}]: give one of 'template' (files under tools/results/) "
                             "and 'builtin' (a built-in scene's name)")
    runs = t.get("run", [])
    _check_runs(runs, str(path))
    for i, splice in enumerate(t.get("splice", [])):
        check_table(splice, SPLICE_KEYS, f"{path}: splice[{i}]", required=("file", "marker", "template"))
    return Section(name, path, t.get("template", f"{name}.md"), t.get("vars", {}), t.get("scenes", {}), runs,
                   t.get("splice", []))
