"""The version of these bindings: the version of the C library they are written for (the
project() version in CMakeLists.txt; the tests check that the library loaded reports it). Kept
as a literal so that setuptools reads it without importing the package (which loads liblfem)."""

__version__ = "0.5.0"
