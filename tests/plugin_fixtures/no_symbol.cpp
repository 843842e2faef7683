// A shared library that is not a lancer plugin: it exports no descriptor.
extern "C" __attribute__((visibility("default"))) int lancer_fixture_not_a_plugin() {
    return 42;
}
