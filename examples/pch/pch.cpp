// Compiles examples/pch/pch.hpp once (see the top-level CMakeLists.txt).
