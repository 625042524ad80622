// TIFF inputs for tests/fuzz/corpus/image: tiled16.tif (a seed for the tiled path) and the regression
// crash-ycbcr-subsampled.tif (4x4 chroma subsampling: rows shorter than width x 3 samples). README.md.
#include <tiffio.h>
#include <cstdint>
#include <string>
#include <vector>
int main(int, char** argv) {
  const std::string dir = argv[1];
  {
    TIFF* t = TIFFOpen((dir + "/tiled16.tif").c_str(), "w");
    TIFFSetField(t, TIFFTAG_IMAGEWIDTH, 20); TIFFSetField(t, TIFFTAG_IMAGELENGTH, 18);
    TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, 8); TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, 1);
    TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK); TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(t, TIFFTAG_TILEWIDTH, 16); TIFFSetField(t, TIFFTAG_TILELENGTH, 16);
    std::vector<std::uint8_t> tile(256);
    for (int i = 0; i < 256; ++i) tile[i] = std::uint8_t(i);
    for (int ty = 0; ty < 18; ty += 16) for (int tx = 0; tx < 20; tx += 16) TIFFWriteTile(t, tile.data(), tx, ty, 0, 0);
    TIFFClose(t);
  }
  {
    TIFF* t = TIFFOpen((dir + "/crash-ycbcr-subsampled.tif").c_str(), "w");
    const int w = 64, h = 4;
    TIFFSetField(t, TIFFTAG_IMAGEWIDTH, w); TIFFSetField(t, TIFFTAG_IMAGELENGTH, h);
    TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, 8); TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, 3);
    TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_YCBCR); TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(t, TIFFTAG_YCBCRSUBSAMPLING, 4, 4); TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, h);
    // One 4x4 block per 4 pixels: 16 Y + Cb + Cr = 18 bytes; the strip holds w/4 blocks.
    std::vector<std::uint8_t> strip(std::size_t(w / 4) * 18, 100);
    TIFFWriteRawStrip(t, 0, strip.data(), tmsize_t(strip.size()));
    TIFFClose(t);
  }
}
