// A CAD reader module built against another interface than this swept's: swept must refuse to
// call it (tests/io/cad_module_test.cpp). It exports the module's two entry points by name only.
extern "C" __attribute__((visibility("default"))) const char* swept_cad_abi() { return "swept-0.0.0-another-interface"; }

extern "C" __attribute__((visibility("default"))) void swept_cad_read(const void*, void*, void*) {
  __builtin_trap();  // never called: the interface check refuses the module first
}
