#include "plan/image_formats.h"

namespace shadowc {
namespace {

ImageFormat bySize(int channels, ImageFormat r, ImageFormat rg, ImageFormat rgba) {
  return channels == 1 ? r : channels == 2 ? rg : rgba;
}

}  // namespace

int momentChannels(Warp warp) {
  switch (warp) {
    case Warp::Linear:
      return 2;
    case Warp::Exp:
      return 1;
    case Warp::Evsm2:
      return 2;
    case Warp::Evsm4:
      return 4;
    case Warp::PowerCdf:
      return 4;
  }
  return 4;
}

ImageFormat momentsFormat(const FilterSpec& spec) {
  const int c = momentChannels(spec.moments.warp);
  // A SAT re-encodes the moments anyway; its input keeps full precision.
  const StorageFormat f = spec.storage.sat != SatKind::None ? StorageFormat::Fp32 : spec.storage.format;
  switch (f) {
    case StorageFormat::Fp32:
      return bySize(c, ImageFormat::R32F, ImageFormat::RG32F, ImageFormat::RGBA32F);
    case StorageFormat::Fp16:
      return bySize(c, ImageFormat::R16F, ImageFormat::RG16F, ImageFormat::RGBA16F);
    case StorageFormat::Unorm16:
      return bySize(c, ImageFormat::R16Unorm, ImageFormat::RG16Unorm, ImageFormat::RGBA16Unorm);
  }
  return ImageFormat::RGBA32F;
}

ImageFormat satFormat(const FilterSpec& spec) {
  const int c = momentChannels(spec.moments.warp);
  if (spec.storage.sat == SatKind::Int32)
    return bySize(c, ImageFormat::R32UI, ImageFormat::RG32UI, ImageFormat::RGBA32UI);
  return bySize(c, ImageFormat::R32F, ImageFormat::RG32F, ImageFormat::RGBA32F);
}

}  // namespace shadowc
