// Linked into the probe_stale_api test plugin: it claims to have been built
// against Rix API version 1, as a plugin compiled before the headers changed
// would. (This definition is strong, so it replaces the weak one the Rix
// headers give every plugin.)
extern "C" __attribute__((visibility("default"))) int RixPluginApiVersion() { return 1; }
