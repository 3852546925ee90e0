"""docs/python.md's example: three glint methods against the ground truth on the area-light scene."""
import glintlab

lab = glintlab.Lab("builtin:glint-area-lights", width=160, height=90, spp="64")
result = lab.compare("conventional,deliot2023,kneiphof2024")
print(f"{'method':<16}{'rmse':>8}{'flip':>8}{'sparkle':>9}")
for name, m in result["methods"].items():
    print(f"{name:<16}{m['rmse']:8.3f}{m['flip_ldr']:8.3f}{m['sparkle_distance']:9.3f}")
floor = result["reference"]
print(f"{'(half-refs)':<16}{'':>8}{floor['flip_ldr_floor']:8.3f}{floor['sparkle_floor']:9.3f}")
