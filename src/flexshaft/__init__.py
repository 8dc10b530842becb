"""flexshaft: high-flexibility rotorcraft tail-rotor driveline design."""
__version__ = "0.1.0"
