// The host of the tests' precompiled header (tests/main/precompiled.hpp): nothing of its own.
