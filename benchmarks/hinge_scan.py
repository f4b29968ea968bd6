"""Check of the optimal hinge's scan (rockcli.mechanisms.catalogue.HINGE_SCAN): the flexures
of the two-storey façade with one to three loads at random heights, weights and levers inside
its storeys, and random storey thicknesses; for each, α0 at the hinge found against the
lowest α0 of a scan of 4001 heights and of the attachment heights. Prints the worst excess
(the search finds the minimum when it is at rounding, ~1e-16).

    python benchmarks/hinge_scan.py [SEED] [VARIANTS]     # default 0, 40 (about a minute)
"""

from __future__ import annotations

import random
import sys
import tempfile
from dataclasses import replace
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

ROOT = Path(__file__).resolve().parents[1]
FINE = 4000


def variant(rng: random.Random) -> str:
    """The example's model with random storey thicknesses and one to three more loads."""
    text = (ROOT / "examples" / "two-storey-facade.toml").read_text(encoding="utf-8")
    text = text.replace("thickness = 0.60     # m", f"thickness = {rng.uniform(0.5, 0.9):.3f}")
    for j in range(rng.choice([1, 2, 3])):
        text += (f'\n[[loads]]\nname = "extra {j}"\nweight = {rng.uniform(2, 120):.3f}\n'
                 f"height = {rng.uniform(0.3, 7.4):.4f}\n"
                 f"from_pivot = {rng.uniform(0.0, 0.44):.4f}\n")  # fmt: skip
    return text


def main(seed: int, variants: int) -> None:
    from rockcli.codecheck.kinematic import Mechanism as SideCheck
    from rockcli.codecheck.kinematic import alpha0
    from rockcli.errors import InputError
    from rockcli.mechanisms.catalogue import HINGE_SCAN, flexure_range
    from rockcli.model.catalogue import catalogue, placed
    from rockcli.model.load import load_model

    rng = random.Random(seed)
    worst, flexures = 0.0, 0
    with tempfile.TemporaryDirectory() as tmp:
        model_file = Path(tmp) / "wall.toml"
        for _ in range(variants):
            model_file.write_text(variant(rng), encoding="utf-8")
            try:
                mechanisms = catalogue(load_model(model_file))
            except InputError:  # a load outside the wall drawn: another variant
                continue
            for m in mechanisms:
                if m.spec.type.value != "vertical-flexure" or m.wall is None:
                    continue
                wall, spec = m.wall, m.spec

                def smallest(z: float, wall=wall, spec=spec, sides=m.sides) -> float:
                    at = replace(spec, hinge_height=z)
                    return min(alpha0(SideCheck(placed(wall, at, s))) for s in sides)

                lo, hi = flexure_range(wall, spec.storey)
                attached = [ld.z for ld in wall.loads] + [r.z for r in wall.restrainers]
                fine = [lo + (hi - lo) * k / FINE for k in range(FINE + 1)]
                lowest = min(smallest(z) for z in fine + [z for z in attached if lo < z < hi])
                excess = (smallest(spec.hinge_height) - lowest) / abs(lowest)
                worst, flexures = max(worst, excess), flexures + 1
    print(f"HINGE_SCAN = {HINGE_SCAN}: {flexures} flexures, worst excess of α0 over the lowest "
          f"of {FINE + 1} heights: {worst:.2e}")  # fmt: skip


if __name__ == "__main__":
    main(
        int(sys.argv[1]) if len(sys.argv) > 1 else 0, int(sys.argv[2]) if len(sys.argv) > 2 else 40
    )
