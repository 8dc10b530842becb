"""Studies layer: analyses combined into the answers a designer asks for."""
