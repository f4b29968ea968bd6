"""Record suites: a set of scaled records and the target spectrum they must match (NTC
§3.2.3.6), read from a TOML suite file, and the check of their mean spectrum against it."""
