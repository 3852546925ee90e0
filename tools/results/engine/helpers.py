"""The names a template can call (docs/results-program.md lists them): measured values of runs by
id, their standard output, formatting, the ranking notes and the pictures copied into docs/images."""

import math
import os

from . import markdown
from .errors import InputError
from .numbers import plain_number, short
from .template import render


class Helpers:
    def __init__(self, outputs, root, images_dir, images_link):
        self.o = outputs          # engine.metrics.Outputs
        self.root = root          # tools/results/
        self.images_dir = images_dir  # where pictures go (docs/images)
        self.images_link = images_link  # how docs/results.md links them ("images")
        self.copies = []          # (source, target), made once every section has rendered

    def names(self):
        o = self.o
        return {
            # A run's top-level values, and its methods' (compare and animate: metrics.json; bench: bench.json).
            "field": o.field, "metric": o.metric, "methods": o.methods,
            "noise": lambda run: o.field(run, "reference_noise_rmse"),
            "energy_error": lambda run: o.field(run, "reference_energy_error"),
            "floor": lambda run: o.field(run, "flicker_floor"),
            "rmse": lambda run, m: o.metric(run, m, "rmse"),
            "energy": lambda run, m: o.metric(run, m, "energy_ratio"),
            "mean_rmse": lambda run, m: o.metric(run, m, "mean_rmse"),
            "flicker": lambda run, m: o.metric(run, m, "flicker"),
            # FLIP, HDR-FLIP and the sparkle distance: compare's, or animate's means over frames.
            "flip": lambda run, m: self.perceptual(run, m, "flip_ldr"),
            "hdr_flip": lambda run, m: self.perceptual(run, m, "flip_hdr"),
            "sparkle": lambda run, m: self.perceptual(run, m, "sparkle_distance"),
            "perceptual_floor": lambda run, key: o.field(run, "reference_floor")[key],
            "ms": lambda run, m: o.metric(run, m, "wall_ms_median"),
            "gpu_ms": lambda run, m: o.metric(run, m, "gpu_ms_median"),
            "entries": lambda run: o.field(run, "methods"),
            "prefilter": self.prefilter, "levels": self.levels, "mean_of": mean_of,
            # What a run printed, and how long it took.
            "stdout": lambda run: o.record(run)["stdout"], "seconds": lambda run: o.record(run)["seconds"],
            "printed_table": self.printed_table, "lines": lines,
            # Sentences and pictures.
            "ranking_note": self.ranking_note, "gap_note": self.gap_note, "metrics_note": self.metrics_note,
            "thumbnails": self.thumbnails, "image": self.image, "plot": self.plot,
            "curves": lambda run: o.field(run, "curves"),
            **PURE,
            # The machine.
            "device": self.device, "cores": lambda: len(os.sched_getaffinity(0)),
        }

    def prefilter(self, run):
        """The report of the first material of a prefilter run."""
        return self.o.metrics(run)[0]

    def levels(self, run):
        """A prefilter run's levels, each with its 'level' index and its 'accuracy' entry (None if
        the run measured none)."""
        p = self.prefilter(run)
        accuracy = p.get("accuracy") or []
        return [dict(v, level=i, accuracy=accuracy[i] if i < len(accuracy) else None)
                for i, v in enumerate(p["levels"])]

    def printed_table(self, run):
        """What compare or animate printed, without its last line ("written to DIR/") and the line
        break before it."""
        return "\n".join(self.o.record(run)["stdout"].splitlines()[:-1])

    def device(self):
        """The GL renderer `glintlab info` names (the run 'info' of results.toml)."""
        for line in self.o.record("info")["stdout"].splitlines():
            if line.startswith("renderer:"):
                return line[len("renderer:"):].strip()
        raise InputError("run 'info' printed no 'renderer:' line")

    def _partial(self, name, **values):
        path = self.root / "templates" / "partials" / name
        text = render(path.read_text(), dict(self.names(), **values), f"tools/results/templates/partials/{name}")
        return text.rstrip("\n")

    def perceptual(self, run, method, key):
        """A compare run's `key` of a method, or an animate run's mean of it over frames."""
        entry = self.o.entry(run, method)
        return self.o.metric(run, method, key if key in entry else "mean_" + key)

    def metrics_note(self, run, methods=None):
        """Which method each metric of a compare run ranks first (among `methods`, default all), and
        whether its lead over the next is more than the reference's own noise (RMSE: twice its noise
        RMSE; FLIP, HDR-FLIP, sparkle: what two half-references score against each other): one
        sentence, saying whether RMSE agrees with the others."""
        names = methods or self.o.methods(run)
        if len(names) < 2:
            return ""
        floors = self.o.field(run, "reference_floor")
        metrics = (("RMSE", "rmse", 2 * self.o.field(run, "reference_noise_rmse")),
                   ("FLIP", "flip_ldr", floors["flip_ldr"]), ("HDR-FLIP", "flip_hdr", floors["flip_hdr"]),
                   ("the sparkle distance", "sparkle_distance", floors["sparkle_distance"]))
        best, parts = {}, []
        for label, key, floor in metrics:
            ranked = sorted(names, key=lambda m: self.perceptual(run, m, key))
            value = lambda m: self.perceptual(run, m, key)  # noqa: E731
            # Methods with the same value (identical images) tie: the lead is over the first that differs.
            first = [m for m in ranked if value(m) == value(ranked[0])]
            best[label] = set(first)
            who = f"`{first[0]}`" if len(first) == 1 else " and ".join(f"`{m}`" for m in first) + " (tied)"
            rest = ranked[len(first):]
            gap = value(rest[0]) - value(ranked[0]) if rest else 0.0
            parts.append(f"{label} ranks {who} first" +
                         ("" if rest and gap > floor else
                          f" (by {gap:.4f}, within the reference's noise {floor:.4f}: not a ranking)" if rest else
                          " (every method the same)"))
        agree = [label for label in ("FLIP", "HDR-FLIP", "the sparkle distance") if best[label] & best["RMSE"]]
        tail = (" (RMSE agrees with " + " and ".join(agree) + ")") if agree else " (RMSE agrees with none of them)"
        return "; ".join(parts) + tail + "."

    def ranking_note(self, run):
        """Which differences a compare run can rank: the best method, and whether its lead over the
        next is larger than twice the reference's noise RMSE."""
        ranked = sorted(self.o.field(run, "methods"), key=lambda e: e["rmse"])  # stable: ties keep their order
        if len(ranked) < 2:
            return ""
        noise = self.o.field(run, "reference_noise_rmse")
        return self._partial("ranking-note.md", best=ranked[0], second=ranked[1], noise=noise,
                             ranks=ranked[1]["rmse"] - ranked[0]["rmse"] > 2 * noise)

    def gap_note(self, label_a, run_a, method_a, label_b, run_b, method_b):
        """Whether two RMSEs against the same reference rank (the noise is run_a's)."""
        a, b = self.o.metric(run_a, method_a, "rmse"), self.o.metric(run_b, method_b, "rmse")
        noise = self.o.field(run_a, "reference_noise_rmse")
        gap = abs(a - b)
        return self._partial("gap-note.md", label_a=label_a, a=a, label_b=label_b, b=b, gap=gap, noise=noise,
                             ranks=gap > 2 * noise)

    def image(self, run, method, name):
        """Copies a method's picture of a compare run (method 'reference': the reference's) to
        docs/images/NAME.png; the link to it."""
        file = "reference" if method == "reference" else self.o.file_of(run, method)
        source = self.o.out_dir / run / f"{file}.png"
        self.copies.append((source, self.images_dir / f"{name}.png"))
        return f"{self.images_link}/{name}.png"

    def plot(self, run, file, name):
        """Copies a file a run wrote (converge's convergence.svg) to docs/images/NAME; the link to it."""
        source = self.o.out_dir / run / file
        self.copies.append((source, self.images_dir / name))
        return f"{self.images_link}/{name}"

    def thumbnails(self, prefix, run, methods):
        """A row of pictures: the reference, then `methods`, of a compare run, copied to
        docs/images/PREFIX-reference.png and PREFIX-FILE.png (FILE: the method's file name)."""
        header, row = ["reference"], [f"![]({self.image(run, 'reference', prefix + '-reference')})"]
        for m in methods:
            header.append(m)
            row.append(f"![]({self.image(run, m, prefix + '-' + self.o.file_of(run, m))})")
        return markdown.table(header, [row])


def settings(name):
    """A variant's settings, "area=lens" of "podee{area=lens}" ('' for a method's id)."""
    return name[name.index("{") + 1:-1] if name.endswith("}") else ""


def lines(text, containing):
    """The lines of `text` that contain `containing` (as grep prints them); at least one."""
    found = [line for line in text.splitlines() if containing in line]
    if not found:
        raise InputError(f"no line contains '{containing}'")
    return "\n".join(found)


def mean_of(entries, key):
    """The mean of `key` over a list of tables (a prefilter run's accuracy entries)."""
    values = [e[key] for e in entries]
    return sum(values) / len(values)


# What needs no run: experiment files and scene templates see these too.
PURE = {
    "short": short, "plain": plain_number, "sin": math.sin, "cos": math.cos, "sqrt": math.sqrt,
    "radians": math.radians, "pi": math.pi, "abs": abs, "min": min, "max": max, "len": len, "str": str,
    "float": float, "int": int, "settings": settings,
    "joined": lambda names: ",".join(names),  # a list of methods as --methods takes it
}
