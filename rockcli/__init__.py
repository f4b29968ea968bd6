"""rock: out-of-plane seismic assessment of masonry macro-elements."""

__version__ = "0.1.0"
