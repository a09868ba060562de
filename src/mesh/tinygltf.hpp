// tinygltf as the library uses it: no image decoding or encoding (the surface has no textures).
// Every file that includes tinygltf includes it through here, so all see the same declarations;
// src/mesh/io_gltf.cpp defines TINYGLTF_IMPLEMENTATION before including it. Internal.
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
