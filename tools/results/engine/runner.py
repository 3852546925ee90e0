"""Running glintlab (and the tools an experiment names), and remembering what ran.

Each run leaves a record, <out>/.runs/<id>.json: its command line, the seconds it took, its
standard output and a key. The key hashes what decides its outputs: the command line, the
glintlab binary, the scene files it reads and the tool it runs, and the GLINTLAB_* environment.
A run whose record holds the same key and whose outputs exist is not run again (--fresh runs
everything); so a section rerun after an edit of its template takes seconds, and one after a
rebuild of glintlab measures everything again. glintlab caches the references itself."""

import hashlib
import json
import os
import subprocess
import sys
import time
from pathlib import Path

from .errors import RunFailure


def file_digest(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


class Runner:
    def __init__(self, repo, out_dir, glintlab, fresh):
        self.repo = repo
        self.out_dir = out_dir
        self.glintlab = glintlab
        self.fresh = fresh
        self._binary_digest = None
        self._builtins = {}
        self.ran = self.reused = 0

    def binary_digest(self):
        if self._binary_digest is None:
            self._binary_digest = file_digest(self.repo / self.glintlab)
        return self._binary_digest

    def builtin_scene(self, name):
        """`glintlab scenes --print NAME`."""
        if name not in self._builtins:
            self._builtins[name] = self._execute([self.glintlab, "scenes", "--print", name], f"builtin:{name}").stdout
        return self._builtins[name]

    def record_path(self, run_id):
        return self.out_dir / ".runs" / f"{run_id}.json"

    def record(self, run_id):
        """The record of a run that has run (None if it has not)."""
        path = self.record_path(run_id)
        return json.loads(path.read_text()) if path.is_file() else None

    def run(self, run_id, argv, inputs, output, label):
        """Runs `argv` unless its record matches; `inputs`: files whose content decides the outputs
        besides the command line and the binary; `output`: the file or folder it writes (or None)."""
        key = self._key(argv, inputs)
        previous = self.record(run_id)
        if (not self.fresh and previous and previous["key"] == key
                and (output is None or Path(output).exists())):
            self.reused += 1
            return previous
        print(f"results: {label}: {' '.join(argv[1:]) if argv[0] == self.glintlab else ' '.join(argv)}",
              file=sys.stderr, flush=True)
        start = time.monotonic()
        done = self._execute(argv, label)
        record = {"id": run_id, "argv": argv, "key": key, "seconds": time.monotonic() - start, "stdout": done.stdout}
        path = self.record_path(run_id)
        path.parent.mkdir(parents=True, exist_ok=True)
        temporary = path.with_suffix(".tmp")
        temporary.write_text(json.dumps(record, indent=1) + "\n")
        temporary.replace(path)
        self.ran += 1
        return record

    def _key(self, argv, inputs):
        h = hashlib.sha256()
        h.update(json.dumps(argv).encode())
        h.update(self.binary_digest().encode())
        for path in inputs:
            h.update(str(path).encode())
            h.update(file_digest(self.repo / path).encode())
        for name in sorted(os.environ):
            if name.startswith("GLINTLAB_") and name != "GLINTLAB_RESULTS_QUICK":  # quick is in argv already
                h.update(f"{name}={os.environ[name]}".encode())
        return h.hexdigest()

    def _execute(self, argv, label):
        try:
            done = subprocess.run(argv, cwd=self.repo, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        except OSError as e:
            raise RunFailure(f"{label}: cannot run {argv[0]}: {e}") from None
        if done.returncode != 0:
            raise RunFailure(f"{label}: exit {done.returncode}: {' '.join(argv)}\n{done.stderr.strip()[-4000:]}")
        return done
