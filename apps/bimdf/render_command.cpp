#include "render_command.hpp"

#include <algorithm>
#include <iostream>

#include "bimdf/error.hpp"
#include "bimdf/mesh.hpp"
#include "bimdf/metrics.hpp"
#include "number_checks.hpp"
#include "output.hpp"

namespace bimdf::cli {

CLI::App* add_render_command(CLI::App& app, RenderCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "render", "Draw a quad mesh into a PNG (shaded, edges, patch colours, singularities)");
  cmd->add_option("MESH", o.mesh, "An all-quad OBJ mesh (patch groups `g patch_N` coloured)")
      ->required();
  cmd->add_option("-o,--output", o.picture, "The PNG file to write")->required();
  cmd->add_option("--width", o.render.width, "Image width in pixels")
      ->default_val(1200)
      ->check(whole_number_from(16, 8192));
  cmd->add_option("--height", o.render.height, "Image height in pixels")
      ->default_val(900)
      ->check(whole_number_from(16, 8192));
  cmd->add_option("--view", o.view,
                  "Viewing direction X,Y,Z, from the camera towards the mesh (default: "
                  "automatic, along the mesh's thinnest axis)")
      ->expected(3)
      ->delimiter(',')
      ->check(finite_number());
  cmd->add_flag("--no-edges", o.no_edges, "Do not draw the quad edges");
  cmd->add_flag("--no-patches", o.no_patches, "One colour for all quads");
  cmd->add_flag("--base-complex", o.base_complex,
                "Colour the patches of the mesh's base complex (traced from its singular "
                "vertices, as `metrics` counts them) instead of the OBJ's patch groups")
      ->excludes("--no-patches");
  cmd->add_flag("--no-singularities", o.no_singularities,
                "Do not mark irregular vertices (valence 3 blue, 5 red, others green)");
  return cmd;
}

int run_render(RenderCommandOptions o) {
  if (!o.view.empty()) {
    if (o.view[0] == 0 && o.view[1] == 0 && o.view[2] == 0)
      throw UsageError{"--view 0,0,0 is not a direction"};
    o.render.view = {o.view[0], o.view[1], o.view[2]};
  }
  o.render.draw_edges = !o.no_edges;
  o.render.colour_patches = !o.no_patches;
  o.render.mark_singularities = !o.no_singularities;
  QuadMesh mesh = read_obj_quads(o.mesh);
  if (mesh.quads.empty()) throw InputError(o.mesh, "", "no faces: expected an OBJ quad mesh");
  if (o.base_complex) mesh.quad_patch = base_complex_patches(mesh);
  const Image image = render_quad_mesh(mesh, o.render);
  write_output_file(o.picture, encode_png(image), {o.mesh});
  std::cout << "picture       " << o.picture << ": " << image.width << " x " << image.height
            << " pixels, " << mesh.num_quads() << " quads";
  if (o.base_complex)
    std::cout << ", " << *std::max_element(mesh.quad_patch.begin(), mesh.quad_patch.end()) + 1
              << " base-complex patches";
  std::cout << "\n";
  return kOk;
}

}  // namespace bimdf::cli
