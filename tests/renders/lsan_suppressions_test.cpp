// Mesa's OSMesa keeps a small framebuffer record per OSMesaMakeCurrent
// buffer that it never frees, even after unbinding and destroying the
// context (2 kB per test run, all inside libOSMesa.so). Not ours to fix:
// suppressed for LeakSanitizer in this test binary (SREH_SANITIZE builds).
extern "C" __attribute__((used)) const char* __lsan_default_suppressions() { return "leak:libOSMesa.so\n"; }
