// How an ARG stores its whole-shape descriptors: sizes and order of the PANORAMA and spectrum
// values. Format constants: the binary format, its codecs and the builders all read them here.
#pragma once

namespace arg {

// PANORAMA (features/panorama_descriptor.hpp): per frame, six views' low Fourier magnitudes,
// then six views' wavelet statistics; two frames.
inline constexpr int kPanoramaAngular = 16;  // frequencies 0..16 around the axis
inline constexpr int kPanoramaAxial = 8;     // frequencies 0..8 along it
inline constexpr int kPanoramaPerView = (kPanoramaAngular + 1) * (kPanoramaAxial + 1);
inline constexpr int kPanoramaFourier = 6 * kPanoramaPerView;    // 918 values per frame
inline constexpr int kPanoramaLevels = 5;                        // Haar levels: 64x128 to 2x4
inline constexpr int kPanoramaBands = 3 * kPanoramaLevels + 1;   // detail bands and the rest
inline constexpr int kPanoramaWavelet = 6 * kPanoramaBands * 2;  // 192 values per frame
inline constexpr int kPanoramaPerFrame = kPanoramaFourier + kPanoramaWavelet;
inline constexpr int kPanoramaSize = 2 * kPanoramaPerFrame;  // two frames: 2220 values

// Shape-DNA (features/laplace_spectrum.hpp): the first eigenvalues, scaled.
inline constexpr int kSpectrumSize = 20;

}  // namespace arg
