// Placeholder so the library has a source until the runtime lands.
namespace shadowc { int runtimePlaceholder() { return 0; } }
