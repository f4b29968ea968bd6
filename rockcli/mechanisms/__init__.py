"""Local mechanisms of a masonry wall as one-degree-of-freedom chains of rigid blocks."""
