"""Scenes and experiments: presets, simulation, the demo and the paper's Monte-Carlo experiments."""
