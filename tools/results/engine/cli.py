"""tools/results.py: runs the experiments of every section (or of the sections named), renders
their templates and writes docs/results.md, docs/images/, the README's tables and the HTML reports."""

import argparse
import os
import re
import subprocess
import sys
from pathlib import Path

from . import markdown
from .config import read_index, read_section
from .errors import InputError, RunFailure
from .helpers import PURE, Helpers
from .metrics import Outputs
from .runs import command_line, expand, output_of
from .runner import Runner
from .scenes import scene_file_name, scene_text
from .template import render

ROOT = Path(__file__).resolve().parent.parent  # tools/results/
REPO = ROOT.parent.parent


def parse_arguments(argv, section_names):
    p = argparse.ArgumentParser(
        prog="tools/results.py",
        description="Measures every section of docs/results.md (or the SECTIONs named) and writes it, docs/images/, "
                    "the README's tables and the HTML reports (docs/results-program.md).")
    p.add_argument("sections", nargs="*", metavar="SECTION",
                   help=f"sections to measure and splice in (default: all): {', '.join(section_names)}")
    p.add_argument("--fresh", action="store_true", help="run every command again, even those whose record matches")
    p.add_argument("--quick", action="store_true",
                   help="reduced sizes, samples and frames (also GLINTLAB_RESULTS_QUICK=1): a check of the program, "
                        "never numbers to commit")
    p.add_argument("--list", action="store_true", help="print every run's command line and exit")
    p.add_argument("--no-build", action="store_true", help="use the glintlab that is built; install and build nothing")
    p.add_argument("--no-report", action="store_true", help="write no HTML report")
    return p.parse_args(argv)


class Program:
    def __init__(self, args):
        self.index = read_index(ROOT)
        self.args = args
        self.quick = args.quick or os.environ.get("GLINTLAB_RESULTS_QUICK") == "1"
        self.glintlab = f"{self.index.build_dir}/glintlab"
        self.out_dir = REPO / self.index.out
        self.sections = {n: read_section(ROOT, n) for n in self.index.section_names}
        base = dict(PURE, **self.index.vars, quick=self.quick, glintlab=self.glintlab, build=self.index.build_dir)
        self.scopes = {"": base}
        self.runs = {}
        where = f"tools/results/{self.index.source.name}"
        for run in expand(self.index.runs, where, "", base):
            self._add(run)
        for name, s in self.sections.items():
            self.scopes[name] = dict(base, **s.vars)
            for run in expand(s.runs, f"tools/results/experiments/{s.source.name}", name, self.scopes[name]):
                self._add(run)
        self.runner = Runner(REPO, self.out_dir, self.glintlab, args.fresh)
        self.outputs = Outputs(self.runs, self.out_dir, self.runner)
        self.helpers = Helpers(self.outputs, ROOT, REPO / self.index.images, "images")

    def _add(self, run):
        parts = run.id.split("/")
        if not re.fullmatch(r"[A-Za-z0-9._/-]+", run.id) or any(p in ("", ".", "..") for p in parts):
            raise InputError(f"{run.where}: id '{run.id}'; allowed: letters, digits, '.', '_', '-', and '/' between "
                             "folder names (it names the run's folder under the output folder)")
        if run.id in self.runs:
            raise InputError(f"{run.where}: id '{run.id}' is also the id of {self.runs[run.id].where}; allowed: "
                             "one run per id (ids name output folders)")
        self.runs[run.id] = run

    # --- running ---------------------------------------------------------------------------------

    def scene_path(self, run):
        """The --scene of a run: a declared scene written under <out>/scenes/, or as given."""
        if not run.scene:
            return ""
        section = self.sections.get(run.section)
        if section and run.scene in section.scenes:
            table = section.scenes[run.scene]
            where = f"tools/results/experiments/{section.source.name}"
            text = scene_text(run.scene, table, run.bindings, ROOT, where, self.runner.builtin_scene)
            path = self.out_dir / "scenes" / scene_file_name(run.scene, table, run.bindings, where)
            path.parent.mkdir(parents=True, exist_ok=True)
            if not path.is_file() or path.read_text() != text:
                path.write_text(text)
            return str(path.relative_to(REPO))
        return run.scene

    def argv_of(self, run):
        output = output_of(run, self.out_dir)
        argv = command_line(run, self.scene_path(run), output.relative_to(REPO) if output else None,
                            self.glintlab, self.quick)
        inputs = []
        if run.scene and not run.scene.startswith("builtin:"):
            inputs.append(argv[argv.index("--scene") + 1])
        if run.command == "tool":
            inputs.append(argv[0])
        return argv, inputs, output

    def execute(self, runs, label):
        for k, run in enumerate(runs):
            argv, inputs, output = self.argv_of(run)
            self.runner.run(run.id, argv, inputs, output, f"{label} [{k + 1}/{len(runs)}] {run.id}")

    # --- writing ---------------------------------------------------------------------------------

    def render_template(self, name, section):
        path = ROOT / "templates" / name
        if not path.is_file():
            raise InputError(f"tools/results/templates/{name}: does not exist")
        scope = dict(self.scopes[section], **self.helpers.names())
        return render(path.read_text(), scope, f"tools/results/templates/{name}")

    def main(self):
        names = self.index.section_names
        chosen = [n for n in self.args.sections if n != "all"] or names
        for n in chosen:
            if n not in names:
                raise InputError(f"unknown section '{n}'; allowed: all, {', '.join(names)}")
        output = REPO / self.index.output
        whole = chosen == names and not [n for n in self.args.sections if n != "all"]
        if not whole:
            document = output.read_text()
            for n in chosen:  # before anything runs: a section to replace must be there
                markdown.splice_section(document, n, "", self.index.output)
        if self.args.list:
            for run in self.runs.values():
                if run.section in ("", *chosen):
                    print(f"{run.id}: {' '.join(self.argv_of(run)[0])}")
            return 0
        if not self.args.no_build:
            build(self.index)
        self.execute([r for r in self.runs.values() if r.section == ""], "shared")
        bodies, splices = {}, []
        for n in chosen:
            section = self.sections[n]
            self.execute([r for r in self.runs.values() if r.section == n], n)
            bodies[n] = self.render_template(section.template, n)
            for s in section.splices:
                splices.append((s, self.render_template(s["template"], n)))
        # Everything measured and rendered: now the files.
        for source, target in self.helpers.copies:
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(source.read_bytes())
        if whole:
            text = self.render_template(self.index.header, "")
            text += "".join(markdown.section_block(n, bodies[n]) + "\n" for n in names)
        else:
            text = output.read_text()
            for n in chosen:
                text = markdown.splice_section(text, n, markdown.section_block(n, bodies[n]), self.index.output)
        write_atomically(output, text)
        for s, body in splices:
            target = REPO / s["file"]
            write_atomically(target, markdown.splice_marker(target.read_text(), s["marker"], body, s["file"]))
        what = self.index.output if whole else f"the {', '.join(chosen)} section(s) of {self.index.output}"
        warning = " in QUICK mode: do not commit" if self.quick else ""
        print(f"results: wrote {what} ({self.runner.ran} runs, {self.runner.reused} reused){warning}", file=sys.stderr)
        if not self.args.no_report:
            self.write_reports()
        return 0

    def write_reports(self):
        """Every run under <out>: <out>/report/; docs/report/ of the headline runs, only when every
        one of them exists (a run of some sections would otherwise replace it by a part of it)."""
        out = self.out_dir.relative_to(REPO)
        report_dir = self.out_dir / "report"
        if not any(report_dir not in p.parents for name in ("metrics.json", "bench.json")
                   for p in self.out_dir.rglob(name)):
            print(f"results: no report: no compare, animate or bench output under {out} yet", file=sys.stderr)
            return
        check([self.glintlab, "report", "-o", str(out / "report"), str(out)])
        if not self.index.report_headline:
            return
        missing = [r for r in self.index.report_runs if not (self.out_dir / r).is_dir()]
        if missing:
            print(f"results: {self.index.report_headline} kept: {len(missing)} of its runs have not run here "
                  f"({', '.join(missing[:4])}{', ...' if len(missing) > 4 else ''}; measure every section to "
                  "rewrite it)", file=sys.stderr)
            return
        check([self.glintlab, "report", "-o", self.index.report_headline,
               *[str(out / r) for r in self.index.report_runs]])


def check(argv, quiet=False):
    done = subprocess.run(argv, cwd=REPO, stdout=subprocess.DEVNULL if quiet else None)
    if done.returncode != 0:
        raise RunFailure(f"failed: {' '.join(argv)}")


def build(index):
    """What the runs use: the packages (tools/install-deps.sh results) and the build targets."""
    check(["tools/install-deps.sh", "results"])
    check(["cmake", "--preset", "release"], quiet=True)
    targets = [a for t in index.build_targets for a in ("--target", t)]
    check(["cmake", "--build", index.build_dir, "-j", str(len(os.sched_getaffinity(0))), *targets], quiet=True)


def write_atomically(path, text):
    temporary = path.with_name(path.name + ".tmp")
    temporary.write_text(text)
    temporary.replace(path)


def main(argv=None):
    try:
        index = read_index(ROOT)
        args = parse_arguments(sys.argv[1:] if argv is None else argv, index.section_names)
        return Program(args).main()
    except InputError as e:
        print(f"results: error: {e}", file=sys.stderr)
        return 2
    except RunFailure as e:
        print(f"results: failed: {e}", file=sys.stderr)
        return 1
