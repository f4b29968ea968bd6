"""The colours every plot gives the same things."""

#: A run's colour by its polarity (+1: the record as given, −1: mirrored).
POLARITY_COLORS = {1: "tab:blue", -1: "tab:orange"}
