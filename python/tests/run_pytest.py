"""Runs one pytest file for ctest (python/CMakeLists.txt): no cache or bytecode in the source tree;
exit 77 (skipped) when pytest is not installed, unless FRONTPACK_REQUIRE_READERS=1."""

import os
import sys

try:
    import pytest
except ImportError:
    print("pytest is not installed (Debian: python3-pytest)")
    sys.exit(1 if os.environ.get("FRONTPACK_REQUIRE_READERS") == "1" else 77)

sys.exit(pytest.main(["-q", "-p", "no:cacheprovider", "-W", "error"] + sys.argv[1:]))
