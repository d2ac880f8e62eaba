"""The mutation flow's one error type."""


class MutationError(Exception):
    """A mutation run that cannot go on: names what is wrong (a missing tool, a build the table
    lacks, an unmutated design that fails its own vectors)."""
