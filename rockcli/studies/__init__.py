"""Studies of many runs, built on the analyses of one element (rockcli.analyses): a sweep over
a grid of models and records (``sweep``), a record suite (``suite_run``), the sizing of a
tie-rod (``retrofit``), fragility curves (``fragility``); the executors they share
(``parallel``) and the one output-folder machinery (``folder``)."""
