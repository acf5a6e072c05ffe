// The translation unit that owns the tests' precompiled headers (cmake/BunrakuTargets.cmake,
// bunraku_precompile): every test executable reuses them. Nothing else is compiled here.
