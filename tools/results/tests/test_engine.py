"""The results program's engine without glintlab: the template language, numbers as the tables
print them, the ranking notes, runs and their quick-mode rules, scenes, splicing, and that every
experiment file and template of the repository reads. ctest runs it (results_program)."""

import json
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from engine import markdown  # noqa: E402
from engine.config import read_index, read_section  # noqa: E402
from engine.errors import InputError  # noqa: E402
from engine.helpers import PURE, Helpers  # noqa: E402
from engine.metrics import Outputs  # noqa: E402
from engine.numbers import plain_number, short  # noqa: E402
from engine.runs import Run, command_line, expand, quick  # noqa: E402
from engine.scenes import glinty  # noqa: E402
from engine.template import _parse, _tokens, render  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent  # tools/results/


class Templates(unittest.TestCase):
    def test_loops_conditions_and_formats(self):
        text = ("| a |\n{% for x in xs %}\n| {{ x }} |{% for y in ys %} {{ x * y :.1f }} |{% endfor %}\n"
                "{% endfor %}\n{% set n = len(xs) %}{% if n > 2 %}many{% elif n == 2 %}two{% else %}one{% endif %} "
                "podee{area=lens}\n")
        self.assertEqual(render(text, dict(PURE, xs=[1, 2], ys=[0.5, 3]), "t"),
                         "| a |\n| 1 | 0.5 | 3.0 |\n| 2 | 1.0 | 6.0 |\ntwo podee{area=lens}\n")

    def test_a_line_holding_only_a_tag_or_a_comment_disappears(self):
        text = "a\n  {# the method's note #}\n{% if True %}\nb\n{% endif %}\nc\n"
        self.assertEqual(render(text, {}, "t"), "a\nb\nc\n")

    def test_tables_and_f_strings(self):
        scope = dict(PURE, sun={"degrees": 0.25, "spp": 16384})
        text = "{{ f'sun-{plain(sun.degrees)}-{sun.spp}' }} {{ 'x:y' }}"
        self.assertEqual(render(text, scope, "t"), "sun-0.25-16384 x:y")

    def test_errors_name_the_file_and_line(self):
        for text, fragment in [("a\n{{ nope }}", "t:2: name 'nope' is not defined"),
                               ("{% for x in y %}", "without its '{% endfor %}'"),
                               ("{{ a", "'{{' without its '}}'"),
                               ("{% endif %}", "without its '{% if %}'"),
                               ("{{ __import__('os') }}", "name '__import__' is not defined"),
                               ("{{ (lambda: 1)() }}", "Lambda is not allowed"),
                               ("{{ 'a'.upper() }}", "only a table has keys"),
                               ("{{ [1] }}", "a list is not text")]:
            with self.assertRaises(InputError) as e:
                render(text, dict(PURE, y=[1]), "t")
            self.assertIn(fragment, str(e.exception))


class Numbers(unittest.TestCase):
    def test_short_rounds_halves_away_from_zero_and_prints_few_digits(self):
        self.assertEqual(short(0.0295, 3), "0.03")
        self.assertEqual(short(2.5, 0), "3")
        self.assertEqual(short(-2.5, 0), "-3")
        self.assertEqual(short(0.125, 2), "0.13")
        self.assertEqual(short(1108.04, 1), "1108")
        self.assertEqual(plain_number(1e-7), "1e-07")
        self.assertEqual(plain_number(16384.0), "16384")


def write_compare(folder, run_id, rmses, noise):
    d = folder / run_id
    d.mkdir(parents=True)
    methods = [{"method": m, "rmse": r, "file": m.replace("{", ".").replace("}", "")} for m, r in rmses]
    (d / "metrics.json").write_text(json.dumps({"reference_noise_rmse": noise, "methods": methods, "crops": []}))


class RankingNotes(unittest.TestCase):
    """A gap between the best two RMSEs ranks only when it is larger than twice the reference's noise."""

    def note(self, rmses, noise):
        with tempfile.TemporaryDirectory() as t:
            write_compare(Path(t), "r", rmses, noise)
            runs = {"r": Run("r", "compare", "test", "", {})}
            return Helpers(Outputs(runs, Path(t), None), ROOT, Path(t) / "images", "images").ranking_note("r")

    def test_a_gap_larger_than_twice_the_noise_ranks(self):
        self.assertEqual(self.note([("lean", 0.5), ("podee{area=lens}", 0.2), ("conventional", 0.9)], 0.1),
                         "Lowest RMSE: `podee{area=lens}` (0.2); next `lean` (0.5); the gap is larger than twice the "
                         "reference noise (0.1).")

    def test_a_gap_within_twice_the_noise_is_not_a_ranking(self):
        self.assertEqual(self.note([("lean", 0.25), ("podee", 0.2)], 0.0295),
                         "Lowest RMSE: `podee` (0.2); next `lean` (0.25); the gap is within twice the reference noise "
                         "(0.03): not a ranking.")

    def test_one_method_has_no_note(self):
        self.assertEqual(self.note([("lean", 0.25)], 0.1), "")


class MetricsNotes(unittest.TestCase):
    """Each metric's first method, whether its lead is more than the reference's own noise, and ties."""

    def note(self, rows, noise, floors):
        with tempfile.TemporaryDirectory() as t:
            d = Path(t) / "r"
            d.mkdir()
            methods = [dict(method=m, file=m, rmse=r, flip_ldr=f, flip_hdr=h, sparkle_distance=s)
                       for m, r, f, h, s in rows]
            floor = dict(zip(("flip_ldr", "flip_hdr", "sparkle_distance"), floors))
            (d / "metrics.json").write_text(json.dumps(
                {"reference_noise_rmse": noise, "reference_floor": floor, "methods": methods, "crops": []}))
            runs = {"r": Run("r", "compare", "test", "", {})}
            return Helpers(Outputs(runs, Path(t), None), ROOT, Path(t) / "images", "images").metrics_note("r")

    def test_leads_within_the_noise_are_not_rankings_and_identical_methods_tie(self):
        note = self.note([("a", 0.5, 0.10, 0.20, 0.3), ("b", 0.6, 0.10, 0.25, 0.1), ("c", 0.9, 0.30, 0.20, 0.4)],
                         0.01, (0.05, 0.01, 0.05))
        self.assertEqual(note, "RMSE ranks `a` first; FLIP ranks `a` and `b` (tied) first; HDR-FLIP ranks `a` and `c` "
                               "(tied) first; the sparkle distance ranks `b` first (RMSE agrees with FLIP and HDR-FLIP).")
        close = self.note([("a", 0.5, 0.10, 0.2, 0.3), ("b", 0.51, 0.11, 0.3, 0.4)], 0.01, (0.05, 0.01, 0.05))
        self.assertIn("RMSE ranks `a` first (by 0.0100, within the reference's noise 0.0200: not a ranking)", close)
        self.assertIn("FLIP ranks `a` first (by 0.0100, within the reference's noise 0.0500: not a ranking)", close)
        same = self.note([("a", 0.5, 0.1, 0.2, 0.3), ("b", 0.5, 0.1, 0.2, 0.3)], 0.01, (0.05, 0.01, 0.05))
        self.assertIn("RMSE ranks `a` and `b` (tied) first (every method the same)", same)


class Runs(unittest.TestCase):
    def test_for_makes_every_combination_or_one_run_per_table(self):
        raw = [{"id": "a-{{ s }}-{{ spp }}", "command": "compare", "for": {"s": "scenes", "spp": [64, 1024]},
                "scene": "builtin:{{ s }}", "spp": "{{ spp }}"},
               {"id": "b-{{ degrees }}", "command": "compare", "for": [{"degrees": 0.25}, {"degrees": 2}],
                "scene": "builtin:x"}]
        runs = expand(raw, "t", "s", dict(PURE, scenes=["x", "y"]))
        self.assertEqual([r.id for r in runs], ["a-x-64", "a-x-1024", "a-y-64", "a-y-1024", "b-0.25", "b-2"])
        self.assertEqual(runs[1].values["spp"], 1024)

    def test_keys_a_command_does_not_take_are_refused(self):
        with self.assertRaises(InputError) as e:
            expand([{"id": "a", "command": "bench", "spp": 4}], "t", "s", {})
        self.assertIn("key 'spp' is not one of command 'bench'", str(e.exception))

    def test_quick_mode_reduces_samples_sizes_and_frames(self):
        self.assertEqual(quick({"spp": 16384, "width": 1920, "height": 1080, "frames": 12, "bench_frames": 10,
                                "accuracy": 4}, "compare"),
                         {"spp": 256, "width": 480, "height": 270, "frames": 3, "bench_frames": 2, "accuracy": 1})
        self.assertEqual(quick({"spp": 64}, "animate"), {"spp": 4, "frames": 3})
        self.assertEqual(quick({"reference": 1024, "width": 40}, "render"), {"reference": 16, "width": 16})

    def test_command_lines_are_glintlabs_flags(self):
        run = Run("x", "compare", "t", "", {"methods": ["conventional", "podee{area=lens}"], "params": ["lean.a=1"],
                                             "spp": 1024, "frame": 23, "reference_filter": "gaussian:0.5"})
        self.assertEqual(command_line(run, "builtin:s", "out/x", "g", False),
                         ["g", "compare", "-q", "--scene", "builtin:s", "--methods", "conventional,podee{area=lens}",
                          "--param", "lean.a=1", "--spp", "1024", "--frame", "23", "--reference-filter",
                          "gaussian:0.5", "-o", "out/x"])


    def test_converge_takes_its_backends_and_steps(self):
        run = Run("x", "converge", "t", "", {"backends": ["path:deng2022", "path:deng2022{environment_lobes=0}"],
                                              "steps": [1, 4, 16], "reference_backend": "path", "spp": 1024,
                                              "max_depth": 2})
        self.assertEqual(command_line(run, "builtin:s", "out/x", "g", False),
                         ["g", "converge", "-q", "--scene", "builtin:s", "--spp", "1024", "--reference-backend", "path",
                          "--max-depth", "2", "--backends", "path:deng2022,path:deng2022{environment_lobes=0}",
                          "--steps", "1,4,16", "-o", "out/x"])
        self.assertEqual(quick(run.values, "converge")["steps"], [1, 4])


class Scenes(unittest.TestCase):
    def test_glinty_keeps_the_density_and_maps_alpha_to_sigma(self):
        text = 'name = "g"\ntype = "binomial-glints"\nalpha = 0.35\nlog_density = 12\nmicrofacet_roughness = 0.01\n'
        self.assertEqual(glinty(text), 'name = "g"\ntype = "glinty"\nsigma = 0.2475\nlog_density = 12\n')


class Splicing(unittest.TestCase):
    def test_a_section_is_replaced_with_its_markers(self):
        doc = "h\n<!-- section:a -->\nold\n<!-- /section:a -->\n\n<!-- section:b -->\nb\n<!-- /section:b -->\n"
        block = markdown.section_block("a", "new\n")
        self.assertEqual(markdown.splice_section(doc, "a", block, "d"),
                         "h\n<!-- section:a -->\nnew\n<!-- /section:a -->\n\n"
                         "<!-- section:b -->\nb\n<!-- /section:b -->\n")
        with self.assertRaises(InputError):
            markdown.splice_section(doc, "c", block, "d")

    def test_a_marker_keeps_its_lines(self):
        self.assertEqual(markdown.splice_marker("x\n<!-- t -->\nold\n<!-- /t -->\ny\n", "t", "new\n", "f"),
                         "x\n<!-- t -->\nnew\n<!-- /t -->\ny\n")


class TheRepositorysFiles(unittest.TestCase):
    def test_every_experiment_expands_and_every_template_parses(self):
        index = read_index(ROOT)
        ids = set()
        for name in index.section_names:
            section = read_section(ROOT, name)
            scope = dict(PURE, **index.vars, **section.vars, quick=False, glintlab="g", build="b")
            for run in expand(section.runs, name, name, scope):
                self.assertNotIn(run.id, ids)
                ids.add(run.id)
            for template in [section.template] + [s["template"] for s in section.splices]:
                path = ROOT / "templates" / template
                _parse(_tokens(path.read_text(), str(path)), str(path))
        self.assertTrue(set(index.report_runs) <= ids, set(index.report_runs) - ids)

    def test_an_unknown_key_names_the_file_and_the_key(self):
        with tempfile.TemporaryDirectory() as t:
            (Path(t) / "experiments").mkdir()
            (Path(t) / "experiments" / "x.toml").write_text('[[run]]\nid = "a"\ncommand = "compare"\nspp_count = 4\n')
            with self.assertRaises(InputError) as e:
                read_section(Path(t), "x")
            self.assertIn("x.toml: run[0]: unknown key 'spp_count'; allowed: id, for", str(e.exception))


if __name__ == "__main__":
    unittest.main()
