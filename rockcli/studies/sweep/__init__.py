"""`rock sweep`: systemic studies (the study file, its cases, where they run, the output)."""
