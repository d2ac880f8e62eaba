"""The state file of a campaign: JSON lines, so a restarted campaign resumes.

Line 1 is ``{"uvt_campaign": 1, "campaign": <Campaign.identity()>}``; every further line is one
finished shard's result (:func:`.task.run_shard`), appended and flushed by the client as the
shard finishes. A shard whose simulator failed (``error``) is not recorded: a restart runs it
again. A last line cut short by a crash is ignored; a file of another campaign is refused.
"""

from __future__ import annotations

import json
import os
from typing import Dict

from ._model import CampaignError
from .spec import Campaign

VERSION = 1


class StateFile:
    """The state file at ``path`` of campaign ``spec``: :attr:`done` holds the shards it
    recorded (shard → result); :meth:`record` appends one."""

    def __init__(self, path: str, spec: Campaign):
        self.path = path
        self.spec = spec
        self.done: Dict[int, dict] = {}
        ident = spec.identity()
        if os.path.exists(path) and os.path.getsize(path) > 0:
            with open(path) as f:
                lines = f.read().split("\n")
            try:
                head = json.loads(lines[0])
            except json.JSONDecodeError as e:
                raise CampaignError(f"state file {path}: line 1 is not JSON ({e})") from e
            if head.get("uvt_campaign") != VERSION or head.get("campaign") != ident:
                raise CampaignError(
                    f"state file {path} is of another campaign ({head.get('campaign')}), not "
                    f"{ident}: give another file or delete it")
            for n, line in enumerate(lines[1:], start=2):
                if not line.strip():
                    continue
                try:
                    r = json.loads(line)
                except json.JSONDecodeError:
                    if n == len(lines) or all(not l.strip() for l in lines[n:]):
                        break  # a write cut short: that shard runs again
                    raise CampaignError(f"state file {path}: line {n} is not JSON") from None
                k = r.get("shard")
                if not isinstance(k, int) or not 1 <= k <= spec.shards:
                    raise CampaignError(f"state file {path}: line {n} names shard {k!r}, "
                                        f"outside 1..{spec.shards}")
                self.done[k] = r
            self._fix_tail()
        else:
            with open(path, "w") as f:
                f.write(json.dumps({"uvt_campaign": VERSION, "campaign": ident}) + "\n")
                f.flush()
                os.fsync(f.fileno())

    def _fix_tail(self):
        """Drop a partial last line so that appended lines start on their own line."""
        with open(self.path, "rb") as f:
            data = f.read()
        if data and not data.endswith(b"\n"):
            keep = data[: data.rfind(b"\n") + 1]
            with open(self.path, "wb") as f:
                f.write(keep)

    def record(self, result: dict):
        """Append a finished shard's result (not one whose simulator failed)."""
        if result.get("error"):
            return
        with open(self.path, "a") as f:
            f.write(json.dumps(result, sort_keys=True) + "\n")
            f.flush()
            os.fsync(f.fileno())
        self.done[result["shard"]] = result
