# SPDX-License-Identifier: Apache-2.0
"""What fixed_mesh_noise.py and renderpark_compare.py --noise share, standard library only: the
hmcr solve of a scene's patches alone for a variant, and the per-patch relative RMS deviation
from a converged solve.

A variant is a sequence, then words for options: `+both` (`--bidirectional yes`), `+cv`
(`--control-variate constant`) and `+BASIS` (`--basis BASIS`): `sobol+both`, `random+linear`.
"""

import math
import statistics

BASES = ("linear", "bilinear", "quadratic", "cubic")
OPTION_WORDS = {"both": ["--bidirectional", "yes"], "cv": ["--control-variate", "constant"]}


def variant_basis(variant):
    """The basis a variant names, or "" for the constant one."""
    return next((w for w in variant.split("+")[1:] if w in BASES), "")


def hmcr_command(hmcr, scene, variant, seed, rays, out, options=()):
    """`hmcr solve` of `scene` on its patches (`--max-depth 0`: every solve has the same leaves),
    one thread; ValueError names a word the variant cannot have."""
    sequence, *words = variant.split("+")
    command = [hmcr, "solve", scene, "--max-depth", "0", "--threads", "1", "--seed", str(seed),
               "--sequence", sequence, "--rays", str(rays), "-q", "-o", out, *options]
    for word in words:
        if word in OPTION_WORDS:
            command += OPTION_WORDS[word]
        elif word in BASES:
            command += ["--basis", word]
        else:
            raise ValueError(f"variant {variant!r}: a sequence, then +both, +cv and +BASIS "
                             f"({', '.join(BASES)}) if wanted")
    return command


def lit_channels(*references):
    """The (patch, channel) pairs where every reference (B triples, patch by patch) is above 0."""
    return [(p, c) for p in range(len(references[0])) for c in range(3)
            if all(r[p][c] > 0 for r in references)]


def relative_rms(runs, reference, lit):
    """The per-patch deviation: the root of the mean over runs of the mean over the lit
    (patch, channel) pairs of ((B - B_ref) / B_ref)^2."""
    squares = [statistics.fmean(((run[p][c] - reference[p][c]) / reference[p][c]) ** 2
                                for p, c in lit) for run in runs]
    return math.sqrt(statistics.fmean(squares))
