"""Record suites in the time history: the code's rule over the records of a suite."""
