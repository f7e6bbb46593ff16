"""Task panels (import only with the GUI up)."""
