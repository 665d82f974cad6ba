// frepkit map, phase 6: the sound track and the movie.
#include "map_phases.h"

#include "user_error.h"

#include "Media/movie_encoder.h"
#include "Media/tone_synthesis.h"
#include "Media/wav_writer.h"

#include <cstdio>

namespace frepkit::map_run
{

void write_sound(const MapInputs& in, const fs::path& wav, MapRecord& record)
{
  const auto t0 = Clock::now();
  const mapping::Plan& plan = in.plan;
  const mapping::Spec& spec = in.spec;
  frep::media::VoiceFrames voices;
  for (const auto& f : plan.frames)
  {
    std::vector<frep::media::VoiceParams> v;
    for (const auto& voice : f.voices)
    {
      v.push_back({ voice.pitch, voice.loudness, voice.timbre });
    }
    voices.push_back(v);
  }
  const frep::media::SynthesisResult sound =
    frep::media::synthesise(voices, spec.animation.fps, spec.audio.sample_rate);
  if (!sound.ok())
  {
    throw UserError("sound: " + sound.error);
  }
  const frep::media::WavWriteResult written =
    frep::media::write_wav(wav, sound.samples, spec.audio.sample_rate);
  if (!written.ok())
  {
    throw UserError(written.error);
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

void encode_movie(const MapInputs& in,
  MapWorkers& workers,
  const FrameFiles& frames,
  const fs::path* audio,
  const fs::path& movie,
  MapRecord& record)
{
  const auto t0 = Clock::now();
  const mapping::Plan& plan = in.plan;
  const double fps = in.spec.animation.fps;
  frep::media::MovieInput input;
  input.frame_pattern = (frames.directory / frames.pattern).string();
  input.frame_count = static_cast<int>(plan.frames.size());
  input.fps = fps;
  if (audio != nullptr)
  {
    input.audio = *audio;
  }
  frep::media::MovieOptions mo;
  const std::size_t before = workers.units_done();
  mo.progress = [&](const frep::media::MovieProgress& p)
  { workers.show_units(before + p.frames_done / 4.0); };
  const frep::media::MovieResult encoded = frep::media::encode_movie(input, movie, mo);
  if (!encoded.ok())
  {
    throw UserError("movie: " + encoded.error);
  }
  record.files.push_back({ { "file", movie.filename().string() },
    { "kind", "movie" },
    { "frames", plan.frames.size() },
    { "fps", fps },
    { "duration", plan.frames.size() / fps },
    { "audio", audio != nullptr } });
  record.stages.push_back({ "movie", seconds_since(t0), movie.filename().string() });
}

} // namespace frepkit::map_run
