// A traits class that lists the optional hooks it provides gets each one checked: here
// `reverse_orientation` is misspelt `reverse_orientaton`, and flip_normals, which looks for the
// hook, stops the build with a static_assert naming hook::reverse_orientation instead of
// silently taking its general path. The control variant spells the hook right.
#include <hmira/algorithms/orientation/flip_normals.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

struct listed_traits : hmira::mesh_traits<hmira::halfedge_mesh> {
    static constexpr hmira::hook hooks[] = {hmira::hook::reverse_orientation};
    // Hides the inherited hook, so that only the spelling below can supply it.
    static void reverse_orientation() = delete;
#ifdef HMIRA_SNIPPET_OK
    static void reverse_orientation(hmira::halfedge_mesh& m) noexcept { m.reverse_orientation(); }
#else
    static void reverse_orientaton(hmira::halfedge_mesh& m) noexcept { m.reverse_orientation(); }
#endif
};

int main() {
    hmira::halfedge_mesh m;
    (void)hmira::flip_normals<hmira::halfedge_mesh, listed_traits>(m);
}
