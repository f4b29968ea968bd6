"""From a fragility or the code check's ζ_E to risk: the site's hazard curve and the annual
rate of a damage state (:mod:`rockcli.risk.curve`), a fragility document read at the edge
(:mod:`rockcli.risk.fragility`)."""
