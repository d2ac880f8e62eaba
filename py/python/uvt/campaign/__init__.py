"""Sign-off campaigns on Dask distributed.

A campaign (:class:`Campaign`) runs ``shards`` × ``per_shard`` records of a seeded stream
(``uvt.gen``: record *i* is the same whatever the sharding) through a simulator — the model
itself, or a command such as the Verilator runner of ``vectors/dpi/pipe.cpp`` — and checks every
output against the model (``uvt.run``, ``uvt.compare``). Each shard is one Dask task
(:func:`run_shard`) returning counts, the model's coverage bins and the first failing record
decoded with reproducer commands; :func:`run` reduces them in shard order, so the summary is the
same for any number of workers, records finished shards in a state file so that a restarted
campaign resumes, and can stop at the first failure. It runs on a ``LocalCluster``, or on any
``distributed.Client`` (a scheduler address, a ``dask_jobqueue`` cluster). The command line is
``python -m uvt.campaign`` (console script ``uvt-campaign``); docs/campaign.md shows both.

>>> from uvt.campaign import Campaign, run
>>> s = run(Campaign(shards=4, per_shard=1000), workers=2, progress=False)
>>> s.passed, s.records
(True, 4000)
"""

from ._model import CampaignError, shard_range
from .runner import Summary, run
from .spec import Campaign
from .state import StateFile
from .task import run_shard

__all__ = ["Campaign", "CampaignError", "Summary", "StateFile", "run", "run_shard",
           "shard_range"]
