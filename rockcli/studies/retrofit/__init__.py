"""`rock retrofit`: size a tie-rod by both analyses (candidates, run, choose)."""
