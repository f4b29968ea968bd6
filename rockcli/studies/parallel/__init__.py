"""Where studies run: the executors (this process, local worker processes, a dask cluster),
the fork server and worker set-up, and the running of chunks of cases on them. Used by every
study (`rock sweep`, suites in the time history, `rock retrofit`); imports none of them."""
