"""The output folder of a study (`rock sweep`, `rock fragility`): one machinery for all."""
