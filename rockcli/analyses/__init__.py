"""Analyses of one element under one earthquake: the code's kinematic check of a model's
catalogue (``kinematic``, ``catalogue``, ``capacity_check``, ``strength``), the rocking time
history of one of its mechanisms (``assess``, ``rocked``, ``floor``), both side by side
(``compare``), and what a command chooses for them (``choices``). Results as data; the
studies of many runs (rockcli.studies) are built on them."""
