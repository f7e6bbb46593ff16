"""GUI commands (import only with the GUI up)."""


def register_commands():
    """Register the FrameFix commands with FreeCAD; returns their names, in toolbar order."""
    import FreeCADGui
    from .analyze import AnalyzeCommand
    from .blocks import BlocksCommand
    from .correct import CorrectCommand
    from .hex_mesh import HexMeshCommand
    commands = [("FrameFix_Analyze", AnalyzeCommand()), ("FrameFix_Correct", CorrectCommand()),
                ("FrameFix_Blocks", BlocksCommand()), ("FrameFix_HexMesh", HexMeshCommand())]
    for name, command in commands:
        FreeCADGui.addCommand(name, command)
    return [name for name, _ in commands]
