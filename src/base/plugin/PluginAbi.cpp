// Compiled into each plugin (CMakeLists.txt, zrender_plugin): the interface tag of the build
// that made it, which pluginObject (base/Plugin.cpp) compares with its own before it calls the
// plugin's factory.

extern "C" __attribute__((visibility("default"))) const char* zrenderPluginAbi() {
  return ZRENDER_PLUGIN_ABI;
}
