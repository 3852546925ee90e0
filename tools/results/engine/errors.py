"""The two ways the results program stops: bad input (exit 2) and a failed command (exit 1)."""


class InputError(Exception):
    """A file of the program's own input is wrong: the message names the file, the key or line,
    the value and what is allowed. Nothing has been written when it is raised."""


class RunFailure(Exception):
    """A command the program ran failed; the message holds its command line and its stderr."""
