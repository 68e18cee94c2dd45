#include "render/video_writer.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <cstdarg>
#include <mutex>

#include "core/errors.hpp"
#include "render/render_error.hpp"

namespace gearsim::render {
namespace {

// FFmpeg's own log lines (libx264's banner and statistics included) would go to stderr; libraries
// never print. The callback keeps the last error line of this thread for the RenderError message.
// It is process-wide: installed once, the first time a VideoWriter is made.
thread_local std::string last_av_error;

void on_av_log(void* avcl, int level, const char* format, va_list args) {
  if (level > AV_LOG_ERROR) return;
  char line[512];
  int prefix = 1;
  av_log_format_line2(avcl, level, format, args, line, sizeof line, &prefix);
  last_av_error = line;
  while (!last_av_error.empty() && (last_av_error.back() == '\n' || last_av_error.back() == '\r')) last_av_error.pop_back();
}

std::string av_error(int code) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, buf, sizeof buf);
  std::string s = buf;
  if (!last_av_error.empty()) s += " (" + last_av_error + ")";
  return s;
}

void check(int code, const std::string& what) {
  if (code < 0) throw RenderError("FFmpeg: " + what + ": " + av_error(code));
}

}  // namespace

void validate_video_settings(const VideoSettings& s) {
  if (s.width_px < 2 || s.height_px < 2 || s.width_px % 2 || s.height_px % 2)
    throw InputError("video settings: " + std::to_string(s.width_px) + "×" + std::to_string(s.height_px) +
                     " px: width_px and height_px must be even and ≥ 2 (yuv420p)");
  if (s.frames_per_second < 1 || s.frames_per_second > 1000)
    throw InputError("video settings: frames_per_second must lie in [1, 1000], got " + std::to_string(s.frames_per_second));
  if (s.crf < 0 || s.crf > 51) throw InputError("video settings: crf must lie in [0, 51], got " + std::to_string(s.crf));
  if (s.preset.empty()) throw InputError("video settings: preset must not be empty");
}

struct VideoWriter::Impl {
  std::filesystem::path path;
  VideoSettings settings;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  SwsContext* sws = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  bool header_written = false, finished = false;
  int frames = 0;

  ~Impl() {
    if (format && format->pb) avio_closep(&format->pb);
    avformat_free_context(format);
    avcodec_free_context(&codec);
    sws_freeContext(sws);
    av_frame_free(&frame);
    av_packet_free(&packet);
  }

  void open() {
    static std::once_flag quiet;
    std::call_once(quiet, [] { av_log_set_callback(on_av_log); });
    last_av_error.clear();
    const AVCodec* encoder = avcodec_find_encoder_by_name(constants::kVideoEncoderName);
    if (!encoder)
      throw RenderError(std::string("FFmpeg: no '") + constants::kVideoEncoderName +
                        "' H.264 encoder in this libavcodec (build FFmpeg with --enable-libx264, or install "
                        "Debian's libavcodec59 which has it)");
    check(avformat_alloc_output_context2(&format, nullptr, "mp4", path.c_str()), "cannot set up an MP4 muxer");
    format->flags |= AVFMT_FLAG_BITEXACT;  // no library version strings in the file
    codec = avcodec_alloc_context3(encoder);
    if (!codec) throw RenderError("FFmpeg: out of memory for the encoder");
    codec->width = settings.width_px;
    codec->height = settings.height_px;
    codec->pix_fmt = AV_PIX_FMT_YUV420P;
    codec->time_base = AVRational{1, settings.frames_per_second};
    codec->framerate = AVRational{settings.frames_per_second, 1};
    codec->thread_count = constants::kVideoEncoderThreads;
    codec->flags |= AV_CODEC_FLAG_BITEXACT;
    codec->color_range = AVCOL_RANGE_MPEG;
    codec->colorspace = AVCOL_SPC_BT709;
    codec->color_primaries = AVCOL_PRI_BT709;
    codec->color_trc = AVCOL_TRC_BT709;
    if (format->oformat->flags & AVFMT_GLOBALHEADER) codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    check(av_opt_set(codec->priv_data, "preset", settings.preset.c_str(), 0), "x264 preset '" + settings.preset + "'");
    check(av_opt_set_int(codec->priv_data, "crf", settings.crf, 0), "x264 crf");
    check(avcodec_open2(codec, encoder, nullptr), "cannot open the libx264 encoder");
    stream = avformat_new_stream(format, nullptr);
    if (!stream) throw RenderError("FFmpeg: out of memory for the video stream");
    stream->time_base = codec->time_base;
    stream->avg_frame_rate = codec->framerate;
    check(avcodec_parameters_from_context(stream->codecpar, codec), "stream parameters");
    if (const int rc = avio_open(&format->pb, path.c_str(), AVIO_FLAG_WRITE); rc < 0)
      throw InputError("cannot write '" + path.string() + "': " + av_error(rc));
    check(avformat_write_header(format, nullptr), "cannot write the MP4 header");
    header_written = true;
    // RGB (full range) → BT.709 limited-range yuv420p, bit-exact.
    sws = sws_getContext(settings.width_px, settings.height_px, AV_PIX_FMT_RGB24, settings.width_px, settings.height_px, AV_PIX_FMT_YUV420P,
                         SWS_BICUBIC | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr, nullptr, nullptr);
    if (!sws) throw RenderError("FFmpeg: cannot set up RGB → yuv420p conversion");
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    sws_setColorspaceDetails(sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
    frame = av_frame_alloc();
    packet = av_packet_alloc();
    if (!frame || !packet) throw RenderError("FFmpeg: out of memory for frames");
    frame->format = AV_PIX_FMT_YUV420P;
    frame->width = settings.width_px;
    frame->height = settings.height_px;
    check(av_frame_get_buffer(frame, 0), "frame buffer");
  }

  // Sends a frame (null: flush) and writes every packet the encoder returns.
  void encode(AVFrame* f) {
    check(avcodec_send_frame(codec, f), "encoding a frame");
    for (;;) {
      const int rc = avcodec_receive_packet(codec, packet);
      if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF) return;
      check(rc, "receiving a packet");
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      check(av_interleaved_write_frame(format, packet), "writing '" + path.string() + "'");
    }
  }

  void finish() {
    if (finished) return;
    finished = true;
    encode(nullptr);
    check(av_write_trailer(format), "writing the MP4 trailer of '" + path.string() + "'");
    check(avio_closep(&format->pb), "closing '" + path.string() + "'");
  }
};

VideoWriter::VideoWriter(const std::filesystem::path& path, const VideoSettings& settings) : impl_(std::make_unique<Impl>()) {
  validate_video_settings(settings);
  impl_->path = path;
  impl_->settings = settings;
  impl_->open();
}

VideoWriter::~VideoWriter() {
  try {
    if (impl_->header_written) impl_->finish();
  } catch (...) {  // a destructor cannot report; finish() can
  }
}

void VideoWriter::add_frame(const Image& image) {
  Impl& v = *impl_;
  if (v.finished) throw InputError("video '" + v.path.string() + "': frame added after finish()");
  if (image.width_px != v.settings.width_px || image.height_px != v.settings.height_px)
    throw InputError("video '" + v.path.string() + "': frame " + std::to_string(v.frames) + " is " + std::to_string(image.width_px) + "×" +
                     std::to_string(image.height_px) + ", expected " + std::to_string(v.settings.width_px) + "×" +
                     std::to_string(v.settings.height_px));
  check(av_frame_make_writable(v.frame), "frame buffer");
  const std::uint8_t* src[1] = {image.rgb.data()};
  const int stride[1] = {3 * image.width_px};
  sws_scale(v.sws, src, stride, 0, image.height_px, v.frame->data, v.frame->linesize);
  v.frame->pts = v.frames;
  v.encode(v.frame);
  ++v.frames;
}

void VideoWriter::finish() { impl_->finish(); }

int VideoWriter::frames_written() const { return impl_->frames; }

}  // namespace gearsim::render
