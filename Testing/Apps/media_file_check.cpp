// Reads what frepkit map writes and prints what the end-to-end test checks (one line each):
//   media_file_check wav FILE [SECONDS]  -> "rate R channels C duration D pitch_start F pitch_end F
//   rms_start A rms_end A peak P"
//                                           (pitch and loudness in the first and last SECONDS,
//                                           default 0.1)
//   media_file_check movie FILE          -> "frames N rate R duration D width W height H audio 0|1
//   audio_duration D"
// Exit code 1 and a message when the file cannot be read.
#include "Media/frequency_analysis.h"
#include "Media/movie_probe.h"
#include "Media/wav_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>

int main(int argc, char** argv)
{
  if (argc < 3)
  {
    std::fprintf(stderr, "usage: %s wav|movie FILE [SECONDS]\n", argv[0]);
    return 2;
  }
  const std::string kind = argv[1];
  if (kind == "wav")
  {
    const frep::media::WavData wav = frep::media::read_wav(argv[2]);
    if (!wav.ok())
    {
      std::fprintf(stderr, "%s\n", wav.error.c_str());
      return 1;
    }
    const double window = argc > 3 ? std::atof(argv[3]) : 0.1;
    const std::size_t n =
      std::min<std::size_t>(wav.frame_count(), static_cast<std::size_t>(window * wav.sample_rate));
    // mono: the first channel
    std::vector<float> mono(wav.frame_count());
    for (std::size_t i = 0; i < mono.size(); ++i)
    {
      mono[i] = wav.samples[i * wav.channels];
    }
    // skip the fade-in/out (10 ms) at the ends
    const std::size_t skip = std::min<std::size_t>(wav.sample_rate / 50, mono.size() / 4);
    const std::span<const float> all(mono);
    const std::span<const float> start = all.subspan(skip, std::min(n, mono.size() - skip));
    const std::span<const float> end = all.subspan(
      mono.size() - skip - std::min(n, mono.size() - skip), std::min(n, mono.size() - skip));
    const auto f0 = frep::media::dominant_frequency(start, wav.sample_rate);
    const auto f1 = frep::media::dominant_frequency(end, wav.sample_rate);
    float peak = 0;
    for (float s : mono)
    {
      peak = std::max(peak, std::abs(s));
    }
    std::printf("rate %d channels %d duration %.6f pitch_start %.3f pitch_end %.3f rms_start %.5f "
                "rms_end %.5f peak %.5f\n",
      wav.sample_rate,
      wav.channels,
      wav.duration(),
      f0 ? *f0 : 0.0,
      f1 ? *f1 : 0.0,
      frep::media::rms(start),
      frep::media::rms(end),
      peak);
    return 0;
  }
  if (kind == "movie")
  {
    frep::media::ProbeOptions options;
    options.count_frames = true;
    const frep::media::MovieProbe movie = frep::media::probe_movie(argv[2], options);
    if (!movie.ok())
    {
      std::fprintf(stderr, "%s\n", movie.error.c_str());
      return 1;
    }
    std::printf(
      "frames %lld rate %.6f duration %.6f width %d height %d audio %d audio_duration %.6f\n",
      movie.frame_count,
      movie.frame_rate,
      movie.duration,
      movie.width,
      movie.height,
      movie.has_audio ? 1 : 0,
      movie.audio_duration);
    return 0;
  }
  std::fprintf(stderr, "unknown kind %s\n", kind.c_str());
  return 2;
}
