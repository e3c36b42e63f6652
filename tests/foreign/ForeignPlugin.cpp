// A plugin from another build, for base/PluginTest.cpp: built as libzrender_foreign.so with an
// interface tag that no build has, and as libzrender_untagged.so with none (a plugin from before
// the tag).

extern "C" {

#ifdef ZRENDER_FOREIGN_TAG
__attribute__((visibility("default"))) const char* zrenderPluginAbi() {
  return ZRENDER_FOREIGN_TAG;
}
#endif

// Never reached: pluginObject refuses the plugin before its factory.
__attribute__((visibility("default"))) void* zrenderForeignPlugin() {
  static int object = 0;
  return &object;
}
}
