"""The scenes that experiments make: a [scenes.NAME] table of an experiment file is either
    template = "scenes/x.toml"       a file under tools/results/ (or several, concatenated), rendered
                                     with the run's names ({{ alpha }}), or
    builtin = "glint-binomial"       a built-in scene as `glintlab scenes --print` gives it,
then edited:
    replace = [["^log_density = .*", "log_density = {{ ld }}"]]   regular expressions, line by line
    transform = "glinty"             a named change of material (TRANSFORMS below)
and written to <out>/scenes/<file> (file: default NAME.toml, a template like the others)."""

import math
import re

from .errors import InputError
from .template import render


def glinty(text):
    """Binomial-glints materials made glinty for the Chermain methods: the same ln density per uv
    area and sigma = alpha / sqrt 2 (Beckmann alpha = sqrt 2 sigma = the GGX alpha); R, the density
    randomization and the slope grid have no counterpart and are dropped (builtin:glint-area-lights-glinty
    is builtin:glint-area-lights made so)."""
    lines = []
    for line in text.splitlines(keepends=True):
        if line.rstrip("\n") == 'type = "binomial-glints"':
            lines.append('type = "glinty"\n')
        elif line.startswith("alpha = "):
            lines.append(f"sigma = {float(line.split()[2]) / math.sqrt(2):.4f}\n")
        elif re.match(r"(microfacet_roughness|density_randomization|slope_grid_scale) = ", line):
            continue
        else:
            lines.append(line)
    return "".join(lines)


TRANSFORMS = {"glinty": glinty}


def scene_text(name, table, scope, root, where, builtin_toml):
    """The TOML of declared scene `name` for a run whose names are `scope`; `builtin_toml(name)`
    prints a built-in scene."""
    at = f"{where}: [scenes.{name}]"
    if "template" in table:
        files = table["template"] if isinstance(table["template"], list) else [table["template"]]
        parts = []
        for f in files:
            path = root / f
            if not path.is_file():
                raise InputError(f"{at}: template '{f}' does not exist under tools/results/")
            parts.append(render(path.read_text(), scope, f"tools/results/{f}"))
        text = "".join(parts)
    else:
        text = builtin_toml(table["builtin"])
    for i, pair in enumerate(table.get("replace", [])):
        if not (isinstance(pair, list) and len(pair) == 2 and all(isinstance(p, str) for p in pair)):
            raise InputError(f"{at}: replace[{i}] is {pair!r}; allowed: [\"pattern\", \"replacement\"]")
        pattern, replacement = (render(p, scope, f"{at}: replace[{i}]") for p in pair)
        try:
            text, count = re.subn(pattern, replacement.replace("\\", "\\\\"), text, flags=re.M)
        except re.error as e:
            raise InputError(f"{at}: replace[{i}]: '{pattern}' is not a regular expression ({e})") from None
        if count == 0:
            raise InputError(f"{at}: replace[{i}]: '{pattern}' matches no line of the scene")
    if "transform" in table:
        if table["transform"] not in TRANSFORMS:
            raise InputError(f"{at}: transform '{table['transform']}'; allowed: {', '.join(TRANSFORMS)}")
        text = TRANSFORMS[table["transform"]](text)
    return text


def scene_file_name(name, table, scope, where):
    """The file a declared scene is written to under <out>/scenes/."""
    file = render(table.get("file", f"{name}.toml"), scope, f"{where}: [scenes.{name}].file")
    if not re.fullmatch(r"[A-Za-z0-9._-]+\.toml", file) or file.startswith("."):
        raise InputError(f"{where}: [scenes.{name}].file is '{file}'; allowed: a file name of letters, digits, '.', "
                         "'_', '-' ending in .toml")
    return file
