// Image textures of model files: PNG, BMP and TGA decoded by stb_image (Debian's
// libstb-dev), JPEG by libjpeg-turbo (jpeg_texels.h), from a file beside the model or
// from bytes inside it (a glTF buffer or data URI).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "skylit/material/texture.h"

namespace skylit {

// The largest texture side read, texels: 16384, as GPUs allow. A larger image (or a
// hostile header claiming one) is refused before its texels are allocated.
inline constexpr int kMaxTextureSide = 16384;

// Decodes PNG, JPEG, BMP or TGA bytes (any channel count; grey and RGB get opaque alpha). Throws
// InputError naming `where` when the bytes are not such an image or it is too large.
std::shared_ptr<const Texture> decode_texture(const unsigned char* bytes, size_t size, TextureEncoding encoding,
                                              const std::string& where);
// The same from a file (a regular file of at most kMaxMeshFileBytes).
// Errors name `path`, after `named_by` if given ("house.gltf: image 2 'brick.png'"): the
// model that names the file says where to look.
std::shared_ptr<const Texture> read_texture_file(const std::filesystem::path& path, TextureEncoding encoding,
                                                 const std::string& named_by = {});

}  // namespace skylit
