// produce, phase 7: the sound track and the movie.
#include "Production/detail/phases.h"

#include "Media/movie_encoder.h"
#include "Media/tone_synthesis.h"
#include "Media/wav_writer.h"

#include <cstdio>

namespace frep::mapping::production
{

void write_sound(const Job& job, const fs::path& wav, Record& record)
{
  const auto t0 = Clock::now();
  const Plan& plan = job.plan;
  const Spec& spec = job.spec();
  media::VoiceFrames voices;
  for (const auto& f : plan.frames)
  {
    std::vector<media::VoiceParams> v;
    for (const auto& voice : f.voices)
    {
      v.push_back({ voice.pitch, voice.loudness, voice.timbre });
    }
    voices.push_back(v);
  }
  const media::SynthesisResult sound =
    media::synthesise(voices, spec.animation.fps, spec.audio.sample_rate);
  if (!sound.ok())
  {
    throw ProductionError("sound: " + sound.error);
  }
  const media::WavWriteResult written = media::write_wav(wav, sound.samples, spec.audio.sample_rate);
  if (!written.ok())
  {
    throw ProductionError(written.error);
  }
  const double duration = static_cast<double>(sound.samples.size()) / spec.audio.sample_rate;
  record.files.push_back({ { "file", wav.filename().string() },
    { "kind", "audio" },
    { "sample_rate", spec.audio.sample_rate },
    { "voices", plan.voice_count },
    { "duration", duration } });
  char detail[64];
  std::snprintf(detail, sizeof detail, "%.2f s, %d voice(s)", duration, plan.voice_count);
  record.stages.push_back({ "audio", seconds_since(t0), detail });
}

void encode_movie(const Job& job,
  Workers& workers,
  const FrameFiles& frames,
  const fs::path* audio,
  const fs::path& movie,
  Record& record)
{
  const auto t0 = Clock::now();
  const Plan& plan = job.plan;
  const double fps = job.spec().animation.fps;
  media::MovieInput input;
  input.frame_pattern = (frames.directory / frames.pattern).string();
  input.frame_count = static_cast<int>(plan.frames.size());
  input.fps = fps;
  if (audio != nullptr)
  {
    input.audio = *audio;
  }
  media::MovieOptions mo;
  const std::size_t before = workers.units_done();
  mo.progress = [&](const media::MovieProgress& p)
  { workers.show_units(before + p.frames_done / 4.0); };
  mo.cancel = [&job] { return job.stopped(); };
  const media::MovieResult encoded = media::encode_movie(input, movie, mo);
  if (encoded.cancelled)
  {
    throw Stopped();
  }
  if (!encoded.ok())
  {
    throw ProductionError("movie: " + encoded.error);
  }
  record.files.push_back({ { "file", movie.filename().string() },
    { "kind", "movie" },
    { "frames", plan.frames.size() },
    { "fps", fps },
    { "duration", plan.frames.size() / fps },
    { "audio", audio != nullptr } });
  record.stages.push_back({ "movie", seconds_since(t0), movie.filename().string() });
}

} // namespace frep::mapping::production
