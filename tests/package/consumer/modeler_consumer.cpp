// Links the render and modeler components of the installed package: the modeler's document is
// usable without a window, and the renderer's camera without a GL context.
#include <cstdio>
#include <stitch/modeler/document.hpp>
#include <stitch/render/camera.hpp>
#include <stitch/stitch.hpp>

int main() {
  stitch::modeler::Document document(stitch::make_cube());
  document.apply_operation("insert-edge 1@1 5@2");
  if (stitch::topology_stats(document.mesh()).genus != 1) return 1;
  document.undo();
  if (stitch::topology_stats(document.mesh()).genus != 0) return 1;
  const stitch::Camera camera = stitch::frame_view(
      stitch::View::front, stitch::bounding_box(document.mesh().positions()), 1.0);
  (void)camera;
  std::printf("modeler consumer: edit, undo and framing work\n");
  return 0;
}
