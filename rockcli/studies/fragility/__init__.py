"""Fragility functions: the probability that a damage state is reached, given the intensity."""
