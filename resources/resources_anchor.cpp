// bunraku_resources carries only compiled Qt resources; this translation unit gives the static
// library a symbol of its own so every toolchain accepts it.
namespace bunraku::resources {
int resourcesAnchor() { return 0; }
} // namespace bunraku::resources
