"""The [ntc.demand.*] tables the code-check tests append to their model files (TOML text).

SOIL_B: the two-storey façade's own demand (examples/two-storey-facade.toml); SOIL_A_FLAT:
plateaus of 2.5·ag with T_C = 0.3 s on soil A, which hand derivations read easily.
"""

SOIL_B = """
[ntc.demand.SLD]
ag = 0.06
F0 = 2.5
Tc_star = 0.27
[ntc.demand.SLV]
ag = 0.15
F0 = 2.5
Tc_star = 0.29
[ntc.demand.SLC]
ag = 0.19
F0 = 2.5
Tc_star = 0.30
"""

SOIL_A_FLAT = """
[ntc.demand.SLD]
ag = 0.05
F0 = 2.5
Tc_star = 0.3
[ntc.demand.SLV]
ag = 0.15
F0 = 2.5
Tc_star = 0.3
[ntc.demand.SLC]
ag = 0.2
F0 = 2.5
Tc_star = 0.3
"""
