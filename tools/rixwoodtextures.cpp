// rixwoodtextures — bakes the procedural wood board (the WoodGrain pattern's
// model, renderer/plugins/stock/patterns/WoodGrainModel.h) into the
// mip-mapped textures the chapter-8 scene reads through PxrTexture, the way
// the course text reads its measured maple:
//   wood_diffuse.tx     diffuse colour (linear RGB)
//   wood_fibercolor.tx  colour of the fiber highlight
//   wood_fiberaxis.tx   fiber direction in the tangent frame (signed floats)
//   wood_beta.tx        width of the fiber highlight (one channel)
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <filesystem>
#include <iostream>

#include "CommandLine.h"
#include "WoodGrainModel.h"

int main(int argc, char** argv) {
    std::string folder;
    int size = 1024;
    CLI::App app{"Bakes the procedural wood board into .tx textures for PxrTexture."};
    app.add_option("folder", folder, "where the textures go")->required();
    app.add_option("--size", size, "pixels on a side")->check(CLI::Range(16, 8192));
    BXDFLAB_PARSE_COMMAND_LINE(app, argc, argv);

    std::filesystem::create_directories(folder);
    woodgrain::Params const model;
    struct Layer {
        char const* name;
        int channels;
    };
    Layer const layers[] = {{"wood_diffuse", 3}, {"wood_fibercolor", 3}, {"wood_fiberaxis", 3}, {"wood_beta", 1}};
    for (Layer const& layer : layers) {
        OIIO::ImageBuf image(OIIO::ImageSpec(size, size, layer.channels, OIIO::TypeDesc::HALF));
        std::vector<float> pixel(static_cast<size_t>(layer.channels));
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                // Pixel centres; t = 0 is the bottom row, as PxrTexture reads with invertT on.
                float s = (static_cast<float>(x) + 0.5f) / static_cast<float>(size);
                float t = 1.0f - (static_cast<float>(y) + 0.5f) / static_cast<float>(size);
                woodgrain::Sample w = woodgrain::evaluate(model, s, t);
                std::string const name = layer.name;
                float const* source = name == "wood_diffuse"      ? w.diffuse
                                      : name == "wood_fibercolor" ? w.fiberColor
                                      : name == "wood_fiberaxis"  ? w.fiberAxis
                                                                  : &w.beta;
                for (int c = 0; c < layer.channels; ++c) pixel[static_cast<size_t>(c)] = source[c];
                image.setpixel(x, y, pixel.data());
            }
        std::string const path = (std::filesystem::path(folder) / (std::string(layer.name) + ".tx")).string();
        OIIO::ImageSpec config;
        if (!OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, image, path, config)) {
            std::cerr << "rixwoodtextures: cannot write " << path << ": " << OIIO::geterror() << "\n";
            return 1;
        }
    }
    std::cout << "rixwoodtextures: wrote 4 textures of " << size << " x " << size << " to " << folder << "\n";
    return 0;
}
