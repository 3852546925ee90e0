#!/usr/bin/env python3
"""Regenerates docs/gpu-timings.md: every method's frame time on the machine's GL device, in one run
of `glintlab bench` per scene (methods take turns frame by frame, so the ratios are fair), with
issue 28's cost targets checked against the ratios measured here.
    tools/gpu-timings.py [--glintlab build/release/glintlab] [--out docs/gpu-timings.md]
                         [--width 1920 --height 1080 --frames 20] [--quick]
Run it on an NVIDIA GPU (about 5 minutes on an H200 with a warm shader cache). On llvmpipe:
    tools/gpu-timings.py --quick --out docs/llvmpipe-timings.md
(640x360, 3 frames, no constant-cost sweep; the llvmpipe targets of issue 28 instead of the GPU's).
Python 3.11's standard library only."""

import argparse
import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# The scenes and the methods timed on each; each table's ratios are to its first method.
ALL_METHODS = "all"
TABLES = [
    ("builtin:spheres", ALL_METHODS,
     "builtin:spheres (no normal-map-glints or glinty material: the glint methods shade it as `conventional`)"),
    ("builtin:normal-glints-noise", "conventional,toksvig,lean,yan2016,deng2022", "builtin:normal-glints-noise (frame 0)"),
]
AREA_METHODS = ("conventional,conventional{area_lights=representative-point},deliot2023,kneiphof2024,"
                "kneiphof2024{light_probability=ggx-ltc},kneiphof2024{subdivision=4x4}")
LIGHT_KINDS = ("quad", "disk", "sphere")
# The scene whose bench also takes the unshaded floor apart (--floor-breakdown).
FLOOR_SCENE = "builtin:spheres"

# Issues 28's and 30's targets: (scene label, method, baseline, largest ratio); on a GPU, and on
# llvmpipe at 640x360 (--quick). Issue 30's sweeps (largest over smallest <= 1.5x) are the
# constant-cost section's ratios.
TARGETS = [("builtin:spheres", "podee", "conventional", 2.5)] + [
    (label, "kneiphof2024", "deliot2023", 1.5)
    for label in ["builtin:glint-area-lights"] + [f"glint-area-lights, {k} light only" for k in LIGHT_KINDS]
] + [("builtin:normal-glints-noise", "deng2022", "conventional", 4.0)]
QUICK_TARGETS = [("builtin:glint-area-lights", "kneiphof2024", "conventional", 2.0),
                 ("builtin:glint-area-lights", "conventional", "conventional{area_lights=representative-point}", 2.0)]


def bench(glintlab, scene, methods, args, floor_breakdown=False):
    command = [str(glintlab), "bench", "--scene", str(scene), "--methods", methods, "--width", str(args.width),
               "--height", str(args.height), "--bench-frames", str(args.frames)]
    if floor_breakdown:
        command.append("--floor-breakdown")
    print("+", " ".join(command), file=sys.stderr, flush=True)
    run = subprocess.run(command, check=True, capture_output=True, text=True)
    return json.loads(run.stdout), " ".join(["glintlab"] + command[1:])


def one_light_scene(kind, directory):
    """builtin:glint-area-lights with only its light of this kind."""
    text = (ROOT / "scenes" / "glint-area-lights.toml").read_text()
    head, *lights = re.split(r"(?m)^\[\[light\]\]\n", text)
    kept = [block for block in lights if re.search(rf'(?m)^type = "{kind}"$', block)]
    if len(kept) != 1:
        sys.exit(f"tools/gpu-timings.py: scenes/glint-area-lights.toml has {len(kept)} {kind} lights, expected 1")
    path = Path(directory) / f"glint-area-lights-{kind}.toml"
    path.write_text(head + "[[light]]\n" + kept[0])
    return path


def table(result, key):
    """The methods' times, "/ first" the ratio of `key` (gpu_ms_median or wall_ms_median)."""
    first = max(result["methods"][0][key], 1e-9)
    rows = ["| method | GPU ms | wall ms | / first |", "| --- | ---: | ---: | ---: |"]
    for m in result["methods"]:
        rows.append(f"| {m['method']} | {m['gpu_ms_median']:.3g} | {m['wall_ms_median']:.3g} | {m[key] / first:.2f} |")
    return "\n".join(rows)


def ratio(result, method, baseline, key):
    times = {m["method"]: m[key] for m in result["methods"]}
    return times[method] / max(times[baseline], 1e-9)


def floor_paragraph(result, key):
    """What the unshaded floor is made of, from the --floor-breakdown rows of one bench."""
    times = {m["method"]: m[key] for m in result["methods"]}
    floor, depth = times["(unshaded)"], times["(unshaded, depth only)"]
    half, one = times["(unshaded, two RGBA16F targets)"], times["(unshaded, one RGBA32F target)"]
    return (f"The floor taken apart (`--floor-breakdown`, the same table): the unshaded frame into two RGBA32F "
            f"colour targets takes {floor:.3g} ms, into one {one:.3g} ms, into two RGBA16F {half:.3g} ms, and with "
            f"no colour target (depth only) {depth:.3g} ms: the colour targets are {max(floor - depth, 0) / max(floor, 1e-9):.0%} "
            f"of the floor, and the rest ({depth:.3g} ms) is clears, vertex work, rasterisation and the fragment "
            f"shader's surface record.")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--glintlab", default=str(ROOT / "build/release/glintlab"))
    parser.add_argument("--out", default=str(ROOT / "docs/gpu-timings.md"))
    parser.add_argument("--width", type=int, default=1920)
    parser.add_argument("--height", type=int, default=1080)
    parser.add_argument("--frames", type=int, default=20)
    parser.add_argument("--sweep-frames", type=int, default=10, help="frames per point of the constant-cost sweep")
    parser.add_argument("--quick", action="store_true", help="640x360, 3 frames, no constant-cost sweep (llvmpipe)")
    args = parser.parse_args()
    if args.quick:
        args.width, args.height, args.frames = 640, 360, 3
    # llvmpipe's timer queries do not time its rendering (it runs at the flush, on the CPU): there
    # the wall clock around each frame, which waits for it, is the time.
    key = "wall_ms_median" if args.quick else "gpu_ms_median"

    sections, commands, results = [], [], {}
    state = {"device": "", "constant_cost": "", "floor": ""}

    def write(complete):
        """The document from what has been measured so far: written after every bench, so that a
        run cut short keeps its tables (and says it was cut short)."""
        checks = ["| target | measured | holds |", "| --- | ---: | --- |"]
        for label, method, baseline, limit in (QUICK_TARGETS if args.quick else TARGETS):
            if label not in results:
                checks.append(f"| {method} <= {limit}x {baseline} on {label} | not measured | |")
                continue
            r = ratio(results[label], method, baseline, key)
            checks.append(f"| {method} <= {limit}x {baseline} on {label} | {r:.2f}x | {'yes' if r <= limit else 'no'} |")
        title = "Timings on llvmpipe" if args.quick else "GPU timings"
        partial = "" if complete else "\n**This run was cut short: the tables below are those it finished.**\n"
        doc = f"""# {title} ({state['device']})
{partial}
Generated by `tools/gpu-timings.py{' --quick' if args.quick else ''}` on {state['device']} through EGL, headless, {args.width}x{args.height}: GPU time
from GL timer queries and the CPU's wall clock around the same frames, medians of {args.frames} timed frames
per method, the methods of a table taking turns frame by frame; "/ first" and the targets are ratios of
{'the wall clock (llvmpipe renders on the CPU at the flush, which its timer queries do not time)' if args.quick else 'GPU time'}
to the table's first method. `(unshaded)` is the same frame with a module that shades nothing (clears, vertex
work, rasterisation, the surface record, and the two RGBA32F colour targets, total and specular, written
at every fragment): the floor under every method. On GH100 (H100/H200) rasterisation and fragment
shading run on a couple of graphics-capable TPCs, so absolute fragment times there are low; the ratios
carry over to other GPUs. Commands:

```sh
{chr(10).join(commands)}
```

## Cost targets (issues 28 and 30)

{chr(10).join(checks)}

## Every method

{(chr(10) * 2).join(sections)}

{state['floor']}
{state['constant_cost']}"""
        Path(args.out).write_text(doc.rstrip() + "\n")

    with tempfile.TemporaryDirectory() as work:
        scenes = [(scene, methods, title) for scene, methods, title in TABLES]
        scenes.append(("builtin:glint-area-lights", AREA_METHODS,
                       "builtin:glint-area-lights (binomial glints under a quad, a disk and a sphere light)"))
        for kind in LIGHT_KINDS:
            scenes.append((one_light_scene(kind, work), AREA_METHODS,
                           f"glint-area-lights, {kind} light only (scenes/glint-area-lights.toml without the others)"))
        for scene, methods, title in scenes:
            breakdown = scene == FLOOR_SCENE
            result, command = bench(args.glintlab, scene, methods, args, breakdown)
            label = title.split(" (")[0]
            results[label] = result
            commands.append(command.replace(str(Path(work)) + "/", ""))
            sections.append(f"{title}:\n\n{table(result, key)}")
            state["device"] = result["device"]
            if breakdown:
                state["floor"] = floor_paragraph(result, key)
            write(complete=False)
        if not args.quick:
            sweep = [str(ROOT / "tools/bench-constant-cost.sh"), args.glintlab, "512", str(args.sweep_frames)]
            print("+", " ".join(sweep), file=sys.stderr, flush=True)
            out = subprocess.run(sweep, check=True, capture_output=True, text=True).stdout
            commands.append(f"tools/bench-constant-cost.sh build/release/glintlab 512 {args.sweep_frames}")
            state["constant_cost"] = ("\n## deng2022's constant cost against yan2016\n\n`tools/bench-constant-cost.sh` at "
                                      "512x512 (docs/results.md, \"Prefiltered glints\", says what it sweeps):\n\n" + out)
    write(complete=True)
    print(f"wrote {args.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
