"""The validation casebook: solved cases with their published sources, run through rock.

Each case file under ``examples/validation/`` (or a folder the user gives) holds cases with
an expected value, its source, a tolerance and its reason, and the input that reproduces it;
:func:`run_casebook` computes each on the same code paths the commands take and returns the
comparison as data (NTC 2018 §10.2: software documented by solved test cases).
"""
