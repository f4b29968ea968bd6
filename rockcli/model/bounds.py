"""Physical ranges of the model file's numbers: a value outside them is a slip, not a wall.

Each bound is wide enough for any masonry element and any laboratory block (the smallest
blocks tested on shaking tables are a few centimetres, a few hundred grams), and narrow
enough that no derived quantity (b, h, R, α, the mass m = W/g, the frequency parameter
p² = 3g/(4R), the stiffness ratios K/m) overflows, underflows to zero or divides by zero
in double precision. Beyond them a number (``weight = 1e-300``, ``radius = 1e300``,
``k = 1.8e308``) used to reach the core and end in OverflowError, ZeroDivisionError or NaN.

Pure: constants only.
"""

from __future__ import annotations

#: Shortest length [m]: 1 mm (a block, a bar diameter, a lever arm). A thickness typed in
#: millimetres (500 for 0.5 m) is within range: :mod:`rockcli.model.plausible` warns of it.
MIN_LENGTH = 1e-3
#: Longest length [m]: 1 km (the tallest masonry tower is about 100 m).
MAX_LENGTH = 1e3
#: Farthest a point of the block can be from its pivot [m]: the diagonal 2R of the largest
#: block (restrainer radius, height and from_pivot).
MAX_REACH = 2 * MAX_LENGTH
#: Most slender block [rad]: α = atan(b/h) of the thinnest, tallest block the lengths allow
#: (1 mm / 1 km); a subnormal α (5e-324) divided by zero in the kinematic check.
MIN_SLENDERNESS = MIN_LENGTH / MAX_LENGTH
#: Smallest elongation at which a restrainer may fail [m]: 1 µm.
MIN_ELONGATION = 1e-6
#: Smallest force of a restrainer's law [N] (yield_pos, yield_neg, anchor_capacity and a
#: non-zero pretension: schema.FORCE_KEYS): 1 N, the weight of 100 g. A member's strength is a
#: device's (a bar, an anchor plate, a vault); below 1 N the value is a slip of units, and the
#: elongation F/K it yields at (1 N / 1e12 N/m = 1e-12 m) stays far above the rounding of the
#: engine's elongations. docs/interpretations.md, "Forces of a restrainer".
MIN_FORCE = 1.0
#: What a pretension accepts (the schema's rule and the derived block's, one wording).
PRETENSION_ALLOWED = (
    f"0, or {MIN_FORCE:g} <= pretension < the yield force and the anchor capacity [N]"
)
#: Lightest weight [kN]: 1e-6 kN = 1 mN, a block of 0.1 g.
MIN_WEIGHT = 1e-6
#: Heaviest weight [kN]: 1e7 kN, a million tonnes (a whole cathedral façade is ~1e5 kN).
MAX_WEIGHT = 1e7
#: Lightest unit weight [kN/m³]: 0.1 (foam, a tenth of water).
MIN_UNIT_WEIGHT = 0.1
#: Heaviest unit weight [kN/m³]: 300 (osmium, the densest element, is 221).
MAX_UNIT_WEIGHT = 300.0
#: Stiffest restrainer [N/m]: 1e12 (a steel bar 1 m² in section, 0.2 m long).
MAX_STIFFNESS = 1e12
#: Softest restrainer given by its stiffness [N/m], when not 0 (no spring on that side):
#: 1 N/m, a millionth of the paper's vault (4e6 N/m). A subnormal k (5e-324) overflowed the
#: elongations F/K and P0/K at which the member yields, breaks or holds its pretension.
MIN_STIFFNESS = 1.0
#: Softest Young's modulus of a tie-rod [Pa]: 1 MPa (rubber).
MIN_MODULUS = 1e6
#: Stiffest Young's modulus [Pa]: 1.2e12 (diamond).
MAX_MODULUS = 1.2e12
#: Smallest spectrum ag [g]: a tenth of the smallest in the NTC hazard grid (0.0089 g at
#: TR = 30 years); a subnormal ag made the capacity/demand ratio infinite.
MIN_AG = 1e-3
#: Shortest spectrum Tc* [s]: a tenth of the smallest in the NTC hazard grid (0.1 s).
MIN_TC_STAR = 0.01
#: Smallest modal participation factor γ and mode-shape ordinate ψ [-] accepted: below it
#: the demand at height underflows.
MIN_MODAL = 1e-3
#: Longest nominal life VN [years] (NTC Tab. 2.4.I: at most 100 for strategic works).
MAX_NOMINAL_LIFE = 1e3
#: Use coefficient CU [-] (NTC Tab. 2.4.II: 0.7, 1.0, 1.5, 2.0).
MIN_USE_COEFFICIENT, MAX_USE_COEFFICIENT = 0.7, 2.0
#: Largest behaviour factor q [-] (the linear kinematic check uses 2).
MAX_BEHAVIOUR_FACTOR = 10.0
#: Most storeys N (the tallest buildings have ~160).
MAX_STOREYS = 200
#: Shortest first period T1 given [s] (the stiffest buildings have T1 ≈ 0.05 s); a T1 of
#: 1e-300 s overflowed the height amplification (T_s/T1)² of the 2009 check.
MIN_PERIOD = 0.01
#: Longest first period T1 [s] (NTC spectra are defined to 4 s; a masonry building is < 1 s).
MAX_PERIOD = 10.0
#: Largest modal participation factor γ [-] (3N/(2N+1) < 1.5 for any N).
MAX_PARTICIPATION = 3.0
#: Largest mode-shape ordinate ψ(Z) [-] (normalised to 1 at the top, NTC C8.7.1.2.1).
MAX_MODE_SHAPE = 1.0
#: Smallest and largest gravity g [m/s²]: the Earth's surface gravity lies between 9.76 m/s²
#: (the summit of Nevado Huascarán) and 9.83 m/s² (the poles); engineers use 9.81, 9.80665
#: or the round 10, all inside. Every unit slip is far outside (g in g: 1; in ft/s²: 32.2;
#: in cm/s²: 981), and so are the values that made m = W/g, p² = 3g/(4R) and the code
#: check's a0* = α0·g/(e*·FC) overflow or vanish (1e300, 1e-300).
MIN_GRAVITY, MAX_GRAVITY = 9.0, 10.0
