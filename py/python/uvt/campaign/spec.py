"""What a campaign is: :class:`Campaign`, checked by :meth:`Campaign.validate`."""

from __future__ import annotations

import hashlib
import json
import os
import shlex
import shutil
from dataclasses import asdict, dataclass
from typing import Optional, Tuple

from ._model import CampaignError, config_for, load, stream_kinds

MODEL = "model"


@dataclass(frozen=True)
class Campaign:
    """A sign-off campaign: ``shards`` × ``per_shard`` records of the seeded stream of ``kind``
    at ``config`` with ``seed`` (record *i* is ``uvt vectors gen``'s record *i*: the same
    whatever the sharding), each shard run through ``simulator`` and checked against the model.

    ``simulator`` is ``"model"`` (the model's own outputs: a self-check of the flow, and with
    ``corrupt`` = a record index whose observed output gets bit ``corrupt_bit`` of word
    ``corrupt_word`` flipped, a check that a difference is found and reported), or a command
    (a string, split as a shell would, without a shell) that reads the shard's input records,
    one per line in the vector files' hex format, and writes one line per record: the input
    words followed by the output words (the pairs ``uvt vectors ver`` reads), or the output
    words alone. The records go to the command's standard input unless it names ``{in}`` (a
    file holding them); it writes to standard output unless it names ``{out}``. ``{seed}``,
    ``{shard}`` (K) and ``{shards}`` (M) are replaced too. ``architectural`` compares only the
    architectural fields (a sample test's ``covered`` and ``depth``). ``timeout`` (seconds) ends
    a simulator that hangs. ``target``: coverage bin names (``uvt.coverage_bins``) the stream is
    biased toward (``uvt vectors gen --target-bins``; still seeded and shard-invariant).
    """

    kind: str = "bsample"
    config: Optional[str] = None
    seed: int = 1
    shards: int = 8
    per_shard: int = 10_000
    simulator: str = MODEL
    architectural: bool = False
    corrupt: Optional[int] = None
    corrupt_word: int = 1
    corrupt_bit: int = 0
    timeout: Optional[float] = None
    target: Tuple[str, ...] = ()

    @property
    def count(self) -> int:
        """Records of the whole campaign (the stream's ``--count``)."""
        return self.shards * self.per_shard

    @property
    def stream_config(self) -> Optional[str]:
        """The configuration the records are made at (``None`` for kinds without one)."""
        return config_for(self.kind, self.config)

    def identity(self) -> dict:
        """What fixes the campaign's results (everything but ``timeout``): a state file
        written for one identity resumes that campaign only."""
        d = asdict(self)
        d.pop("timeout")
        d["config"] = self.stream_config
        d["target"] = list(self.target)  # as JSON holds it (the state file compares)
        return d

    def key(self) -> str:
        """A short hash of :meth:`identity` (names the Dask tasks)."""
        s = json.dumps(self.identity(), sort_keys=True)
        return hashlib.sha256(s.encode()).hexdigest()[:12]

    def command(self) -> list:
        """The simulator command as arguments (empty for the model)."""
        return [] if self.simulator == MODEL else shlex.split(self.simulator)

    def validate(self) -> "Campaign":
        """Check every field; a :class:`CampaignError` names the first that is wrong and what
        is accepted. Returns the campaign."""
        if self.kind not in stream_kinds():
            raise CampaignError(
                f"unknown or stream-less kind {self.kind!r}: a campaign runs one of "
                f"{', '.join(stream_kinds())} (bounds and exact sample-test records name a "
                "triangle of a setup_in file)")
        for name in ("shards", "per_shard", "seed", "corrupt_word", "corrupt_bit"):
            v = getattr(self, name)
            if not isinstance(v, int) or isinstance(v, bool):
                raise CampaignError(f"{name} must be an integer, not {v!r}")
        if self.shards < 1:
            raise CampaignError(f"shards = {self.shards}: a campaign needs at least one shard")
        if self.per_shard < 1:
            raise CampaignError(f"per_shard = {self.per_shard}: a shard needs at least one record")
        if not 0 <= self.seed < 2**64:
            raise CampaignError(f"seed {self.seed} outside 0..2^64-1")
        if self.count >= 2**64:
            raise CampaignError(f"{self.shards} × {self.per_shard} records: over 2^64")
        if self.timeout is not None and not self.timeout > 0:
            raise CampaignError(f"timeout {self.timeout!r}: seconds > 0, or None")
        self._validate_config()
        self._validate_simulator()
        return self

    def _validate_config(self):
        # The stream itself says which configurations a kind is made at (uvt.stream_config).
        cfg = self.stream_config
        try:
            load().gen(self.kind, cfg, self.seed, 1, (1, 1), self.target)
        except Exception as e:  # the model names what it refuses
            raise CampaignError(f"{self.kind} records at {cfg}: {e}") from e

    def _validate_simulator(self):
        if self.simulator == MODEL:
            if self.corrupt is not None and not (
                    isinstance(self.corrupt, int) and 0 <= self.corrupt < self.count):
                raise CampaignError(f"corrupt = {self.corrupt!r}: a record index in "
                                    f"0..{self.count - 1}")
            return
        if self.corrupt is not None:
            raise CampaignError("corrupt is a self-test of the model simulator; an external "
                                "simulator's outputs are its own")
        if not isinstance(self.simulator, str) or not self.simulator.strip():
            raise CampaignError("simulator: 'model' or a command, not an empty string")
        try:
            args = self.command()
        except ValueError as e:
            raise CampaignError(f"simulator command {self.simulator!r}: {e}") from e
        exe = args[0]
        if os.sep in exe:
            ok = os.path.isfile(exe) and os.access(exe, os.X_OK)
        else:
            ok = shutil.which(exe) is not None
        if not ok:
            raise CampaignError(f"simulator {exe!r} not found or not executable (build the "
                                "Verilator runner with `python -m uvt.campaign build-sim`)")
