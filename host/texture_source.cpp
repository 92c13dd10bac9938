#include "texture_source.h"
#include "procedural.h"

namespace tf {

MipChain load_texture(const TextureSource& source)
{
    if (is_procedural(source.name_or_path))
        return make_procedural(source.name_or_path, source.procedural_size);
    return build_mip_chain(read_image(source.name_or_path, source.color, max_texture_dimension));
}

} // namespace tf
