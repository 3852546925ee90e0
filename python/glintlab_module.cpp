// The Python module `glintlab` (docs/python.md): include/glintlab/glintlab.hpp with images as numpy
// arrays (float32, height x width x 3, linear radiance, row 0 at the top) and metrics as dicts.
// The CLI's errors are raised with its messages: InputError (a ValueError: exit 2 in the CLI) and
// RuntimeFailure (a RuntimeError: exit 1).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "glintlab/glintlab.hpp"

namespace py = pybind11;

namespace {

// The image's pixels moved into the array (no copy).
py::array_t<float> to_array(glintlab::RgbImage&& image) {
  auto* pixels = new std::vector<float>(std::move(image.pixels));
  py::capsule owner(pixels, [](void* p) { delete static_cast<std::vector<float>*>(p); });
  return py::array_t<float>({image.height, image.width, 3}, pixels->data(), owner);
}

py::dict rendering_dict(glintlab::Rendering&& r) {
  py::dict d;
  d["total"] = to_array(std::move(r.total));
  d["specular"] = to_array(std::move(r.specular));
  return d;
}

py::dict reference_dict(glintlab::ReferenceRendering&& r) {
  py::dict d;
  d["total"] = to_array(std::move(r.total));
  d["specular"] = to_array(std::move(r.specular));
  d["standard_error"] = to_array(std::move(r.standard_error));
  d["spp"] = r.spp;
  d["passes"] = r.passes;
  d["noise_rmse"] = r.noise_rmse;
  return d;
}

py::dict frame_dict(glintlab::AnimationFrame&& f) {
  py::dict d, renderings;
  d["frame"] = f.frame;
  for (auto& [name, r] : f.renderings) renderings[py::str(name)] = rendering_dict(std::move(r));
  d["renderings"] = renderings;
  d["metrics"] = f.metrics;
  d["reference"] = reference_dict(std::move(f.reference));
  return d;
}

py::list method_list() {
  py::list out;
  for (const glintlab::MethodInfo& m : glintlab::list_methods()) {
    py::list params;
    for (const glintlab::ParameterInfo& p : m.parameters)
      params.append(py::dict(py::arg("name") = p.name, py::arg("description") = p.description,
                             py::arg("default") = p.default_value, py::arg("allowed") = p.allowed,
                             py::arg("choices") = p.choices));
    out.append(py::dict(py::arg("id") = m.id, py::arg("title") = m.title, py::arg("citation") = m.citation,
                        py::arg("summary") = m.summary, py::arg("parameters") = params));
  }
  return out;
}

}  // namespace

PYBIND11_MODULE(glintlab, m) {
  m.doc() = "glintlab: sub-pixel specular highlights and glints, rendered and measured against ground truth";
  py::register_exception<glintlab::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<glintlab::RuntimeFailure>(m, "RuntimeFailure", PyExc_RuntimeError);

  m.def("methods", &method_list,
        "Every method as a dict: id, title, citation, summary, parameters (name, description, default, allowed, "
        "choices), in `glintlab methods`' order.");
  m.def("scenes", &glintlab::list_builtin_scenes, "The built-in scenes' names, 'builtin:<name>'.");

  py::class_<glintlab::Animation>(m, "Animation",
                                  "A camera path frame by frame: iterate it (each frame a dict: frame, renderings, "
                                  "metrics, reference), then summary().")
      .def_property_readonly("frames", &glintlab::Animation::frames)
      .def("__len__", &glintlab::Animation::frames)
      .def("__iter__", [](glintlab::Animation& a) -> glintlab::Animation& { return a; })
      .def("__next__",
           [](glintlab::Animation& a) {
             if (a.done()) throw py::stop_iteration();
             return frame_dict(a.next());
           })
      .def("summary", &glintlab::Animation::summary,
           "Per method mean_rmse, flicker, mean_sparkle_distance, mean_flip_ldr, mean_flip_hdr over the frames "
           "rendered so far; 'reference': flicker_floor, noise_rmse, spp_min, spp_max.");

  py::class_<glintlab::Lab>(m, "Lab", "A scene opened for rendering and measuring (its own headless GL context).")
      .def(py::init([](const std::string& scene, int width, int height, int frames, const std::string& spp,
                       const std::string& reference_backend, const std::vector<std::string>& params, double ppd,
                       bool use_cache, bool quiet) {
             glintlab::LabOptions o;
             o.width = width;
             o.height = height;
             o.frames = frames;
             o.spp = spp;
             o.reference_backend = reference_backend;
             o.params = params;
             o.pixels_per_degree = ppd;
             o.use_cache = use_cache;
             o.quiet = quiet;
             return glintlab::Lab(scene, o);
           }),
           py::arg("scene") = "builtin:every-family", py::arg("width") = 0, py::arg("height") = 0,
           py::arg("frames") = 0, py::arg("spp") = "64", py::arg("reference_backend") = "",
           py::arg("params") = std::vector<std::string>{}, py::arg("ppd") = 0.0, py::arg("use_cache") = true,
           py::arg("quiet") = true,
           "scene: a TOML or glTF file or 'builtin:<name>'; width/height/frames 0: the scene's; spp: the "
           "reference's samples per pixel or 'auto'; params: 'name=value' or 'method.name=value' (as --param); "
           "ppd: FLIP's pixels per degree (0: 67.02).")
      .def_property_readonly("width", &glintlab::Lab::width)
      .def_property_readonly("height", &glintlab::Lab::height)
      .def_property_readonly("frames", &glintlab::Lab::frames)
      .def_property_readonly("scene", &glintlab::Lab::scene)
      .def(
          "render", [](glintlab::Lab& lab, const std::string& method, int frame) {
            return rendering_dict(lab.render(method, frame));
          },
          py::arg("method"), py::arg("frame") = 0,
          "A method or variant 'id{name=value,...}' on one frame: {'total', 'specular'} as float32 HxWx3 arrays.")
      .def(
          "reference", [](glintlab::Lab& lab, int frame) { return reference_dict(lab.reference(frame)); },
          py::arg("frame") = 0,
          "The ground truth of a frame: total, specular, standard_error (arrays), spp, passes, noise_rmse.")
      .def(
          "compare",
          [](glintlab::Lab& lab, const std::string& methods, int frame) {
            glintlab::Comparison c = lab.compare(methods, frame);
            py::dict d;
            d["methods"] = c.methods;
            d["reference"] = c.reference;
            return d;
          },
          py::arg("methods"), py::arg("frame") = 0,
          "Methods (as --methods: a list, variants, 'all') against the reference: {'methods': {name: metrics}, "
          "'reference': {noise_rmse, spp, flip_ldr_floor, flip_hdr_floor, sparkle_floor}}; metrics by "
          "metrics.json's names.")
      .def("animate", &glintlab::Lab::animate, py::arg("methods"), py::keep_alive<0, 1>(),
           "The camera path for the methods, an iterator of frames.");
}
