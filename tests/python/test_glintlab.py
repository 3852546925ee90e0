"""The Python module against the CLI it wraps: the same metrics, the same messages, arrays of the
stated shape. Run by ctest (tests/CMakeLists.txt) with PYTHONPATH at the built module and
GLINTLAB_BINARY the CLI of the same build."""
import json
import os
import subprocess

import numpy as np
import pytest

import glintlab

SCENE = "builtin:spheres"
SIZE = dict(width=48, height=27)
CLI = os.environ["GLINTLAB_BINARY"]


def run_cli(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True)


@pytest.fixture(scope="module")
def lab():
    return glintlab.Lab(SCENE, spp="16", **SIZE)


def test_methods_are_the_clis():
    listed = run_cli("methods")
    assert listed.returncode == 0
    ids = [m["id"] for m in glintlab.methods()]
    assert len(ids) == len(set(ids)) > 10
    for method_id in ids:
        assert method_id in listed.stdout
    deliot = next(m for m in glintlab.methods() if m["id"] == "deliot2023")
    assert deliot["parameters"], "deliot2023 declares parameters"
    for p in deliot["parameters"]:
        assert p["name"] and p["allowed"] and p["default"] != ""


def test_scenes_open(lab):
    assert SCENE in glintlab.scenes()
    assert (lab.width, lab.height) == (48, 27)
    assert lab.frames >= 1


def test_a_scene_file_renders_as_its_builtin(lab, tmp_path):
    printed = run_cli("scenes", "--print", SCENE.split(":")[1])
    assert printed.returncode == 0
    scene_file = tmp_path / "spheres.toml"
    scene_file.write_text(printed.stdout)
    from_file = glintlab.Lab(str(scene_file), **SIZE)
    assert np.array_equal(from_file.render("conventional")["total"], lab.render("conventional")["total"])


def test_render_is_float32_hxwx3_with_its_specular_part(lab):
    r = lab.render("conventional")
    for key in ("total", "specular"):
        assert r[key].shape == (27, 48, 3) and r[key].dtype == np.float32
        assert np.isfinite(r[key]).all()
    assert r["specular"].max() > 0
    # The diffuse part (total - specular) is radiance too: not negative beyond rounding.
    assert (r["total"] - r["specular"]).min() > -1e-5
    # A variant with other settings renders another image.
    blurred = lab.render("toksvig")
    assert blurred["total"].shape == r["total"].shape


def test_compare_gives_the_clis_numbers(lab, tmp_path):
    methods = "conventional,toksvig"
    ours = lab.compare(methods)
    cli = run_cli("compare", "-q", "--scene", SCENE, "--methods", methods, "--spp", "16", "--width", "48",
                  "--height", "27", "-o", str(tmp_path))
    assert cli.returncode == 0, cli.stderr
    theirs = json.loads((tmp_path / "metrics.json").read_text())
    assert ours["reference"]["spp"] == theirs["reference_spp"]
    assert ours["reference"]["noise_rmse"] == pytest.approx(theirs["reference_noise_rmse"], rel=1e-9)
    for row in theirs["methods"]:
        mine = ours["methods"][row["method"]]
        for key in ("rmse", "energy_ratio", "block_rmse", "flip_ldr", "flip_hdr", "sparkle_distance"):
            assert mine[key] == pytest.approx(row[key], rel=1e-6, abs=1e-12), key
    for key, floor in (("flip_ldr_floor", "flip_ldr"), ("sparkle_floor", "sparkle_distance")):
        assert ours["reference"][key] == pytest.approx(theirs["reference_floor"][floor], rel=1e-6)


def test_reference_states_its_noise(lab):
    ref = lab.reference()
    assert ref["spp"] == 16 and ref["passes"] >= 2
    assert ref["standard_error"].shape == (27, 48, 3)
    # noise_rmse is the RMS of the per-pixel standard errors.
    assert ref["noise_rmse"] == pytest.approx(float(np.sqrt(np.mean(ref["standard_error"].astype(np.float64) ** 2))),
                                              rel=1e-4)


def test_animation_frame_by_frame(lab):
    animation = lab.animate("conventional")
    frames = list(animation)
    assert len(frames) == len(animation) == lab.frames
    assert [f["frame"] for f in frames] == list(range(lab.frames))
    summary = animation.summary()
    rmse = [f["metrics"]["conventional"]["rmse"] for f in frames]
    assert summary["conventional"]["mean_rmse"] == pytest.approx(np.mean(rmse), rel=1e-9)
    assert summary["conventional"]["flicker"] > 0
    assert summary["reference"]["spp_max"] == 16


@pytest.mark.parametrize("call, args", [
    ("render", ["nosuch"]),
    ("compare", ["conventional,nosuch"]),
    ("render", ["deliot2023{screen_space_scale=99}"]),
])
def test_bad_input_raises_the_clis_message(lab, call, args, tmp_path):
    with pytest.raises(glintlab.InputError) as raised:
        getattr(lab, call)(*args)
    cli = run_cli("render", "--scene", SCENE, "--method", args[0], "-o", str(tmp_path / "x.exr"))
    assert cli.returncode == 2
    assert str(raised.value) in cli.stderr
    assert not any(tmp_path.iterdir()), "the CLI wrote nothing"


def test_bad_scene_and_frame():
    with pytest.raises(glintlab.InputError, match="no-such-file.toml"):
        glintlab.Lab("no-such-file.toml")
    lab = glintlab.Lab(SCENE, **SIZE)
    with pytest.raises(glintlab.InputError, match="frame 9999: allowed: 0 .. "):
        lab.render("conventional", frame=9999)


def test_several_labs_at_once(lab):
    """Each Lab draws in its own GL context; closing one leaves the others working."""
    before = lab.render("conventional")["total"]
    other = glintlab.Lab("builtin:tubes", width=32, height=18)
    tubes = other.render("conventional")["total"]
    assert np.array_equal(lab.render("conventional")["total"], before)
    del other
    import gc
    gc.collect()
    assert np.array_equal(lab.render("conventional")["total"], before)
    assert tubes.shape == (18, 32, 3) and np.isfinite(tubes).all()
