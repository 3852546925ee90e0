#pragma once
// A resource that is storage buffers, each bound at its binding point (the contract's): the shape of
// deng2022's pyramids, the normal-map elements and the environment's lobes.
#include <cstdint>
#include <utility>
#include <vector>

#include "gl/context.hpp"
#include "gl/objects.hpp"
#include "render/resources/resource.hpp"

namespace glintlab {

class StorageBuffersResource : public GpuResource {
 public:
  /// Uploads `data` to be bound at `binding`; an empty vector becomes one zero word (GL buffers are
  /// never empty).
  template <typename T>
  StorageBuffersResource& add(int binding, const std::vector<T>& data) {
    static_assert(sizeof(T) == 4, "words: uint32 or float");
    const std::uint32_t zero = 0;
    const std::size_t bytes = data.size() * sizeof(T);
    buffers_.emplace_back(binding, data.empty() ? gl::make_buffer(sizeof zero, &zero)
                                                : gl::make_buffer(static_cast<GLsizeiptr>(bytes), data.data()));
    bytes_ += bytes;
    return *this;
  }
  void bind() const override {
    for (const auto& [binding, buffer] : buffers_) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer.id());
  }
  [[nodiscard]] std::uint64_t gpu_bytes() const override { return bytes_; }

 private:
  std::vector<std::pair<int, gl::Buffer>> buffers_;
  std::uint64_t bytes_ = 0;
};

}  // namespace glintlab
