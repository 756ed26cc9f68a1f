// TetGen 1.5.0 (Debian libtet1.5) reports every error through terminatetetgen(m, code),
// which with TETLIBRARY calls m->freememory() and throws the code. freememory() does not
// reset the pool pointers, so unwinding then runs ~tetgenmesh() -> freememory() again on
// the local mesh inside tetrahedralize(): a double delete, SIGSEGV in
// memorypool::~memorypool. Every TetGen error (a self-intersecting facet, a bad switch)
// therefore killed the process instead of reaching our catch.
//
// libtet calls terminatetetgen through the PLT (it is a weak inline symbol), so this strong
// definition replaces it for the whole process: it only throws, and the destructor that
// runs during unwinding frees the mesh exactly once. tetgen.h is deliberately not included
// here: it carries the inline definition this one overrides. Tested by
// tests/tetmesh/tetrahedralize_test.cpp (TetGenErrorIsAnError).
class tetgenmesh;

void terminatetetgen(tetgenmesh* /*mesh freed by its destructor*/, int code) { throw code; }

namespace molmesh::detail {
// Called before every TetGen run: the reference makes the linker take this object file
// (and with it the override above) from the static library.
void link_tetgen_terminate_override() {}
}  // namespace molmesh::detail
