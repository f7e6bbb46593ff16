"""The workbench's errors: each says what happened and what to do next."""


class FrameFixError(Exception):
    """Base of every error the workbench reports to the user."""


class SelectionError(FrameFixError):
    """The selection is not exactly one solid."""


class BackendError(FrameFixError):
    """The backend is missing, failed, crashed, hung or wrote an unreadable report.

    `stage` is the backend's stage when it named one ("load", "mesh", ...), else "".
    """

    def __init__(self, message, stage=""):
        super().__init__(message)
        self.stage = stage
