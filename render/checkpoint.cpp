#include "render/checkpoint.h"

#include <elf.h>
#include <link.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "io/temp_file.h"

namespace tr {
namespace {

constexpr const char* kFormat = "twinray checkpoint ";
constexpr const char* kVersion = "2";  // 2: the pass moments (render/film_moments.h PassMoments)

void write_group(std::ostream& out, const SampleGroup& g) {
  out.write(reinterpret_cast<const char*>(&g.n), sizeof g.n);
  out.write(reinterpret_cast<const char*>(g.mean), sizeof g.mean);
  out.write(reinterpret_cast<const char*>(g.m2), sizeof g.m2);
}

void read_group(std::istream& in, SampleGroup& g) {
  in.read(reinterpret_cast<char*>(&g.n), sizeof g.n);
  in.read(reinterpret_cast<char*>(g.mean), sizeof g.mean);
  in.read(reinterpret_cast<char*>(g.m2), sizeof g.m2);
}

void write_moments(std::ostream& out, const FilmMoments& m) {
  write_group(out, m.positive);
  write_group(out, m.negative);
  write_group(out, m.passes.values);
  out.write(reinterpret_cast<const char*>(&m.passes.signs), sizeof m.passes.signs);
  out.write(reinterpret_cast<const char*>(m.passes.sum), sizeof m.passes.sum);
}

void read_moments(std::istream& in, FilmMoments& m) {
  read_group(in, m.positive);
  read_group(in, m.negative);
  read_group(in, m.passes.values);
  in.read(reinterpret_cast<char*>(&m.passes.signs), sizeof m.passes.signs);
  in.read(reinterpret_cast<char*>(m.passes.sum), sizeof m.passes.sum);
}

std::string header(const RenderIdentity& id, std::uint32_t samples) {
  std::ostringstream h;
  h << kFormat << kVersion << "\n"
    << "build " << id.build << "\n"
    << "scene " << id.scene << "\n"
    << "backend " << id.backend << "\n"
    << "seed " << id.seed << "\n"
    << "granularity " << id.granularity << "\n"
    << "width " << id.width << "\n"
    << "height " << id.height << "\n"
    << "aovs " << id.aov_count << "\n"
    << "pass_size " << id.pass_size << "\n"
    << "samples " << samples << "\n"
    << "end\n";
  return h.str();
}

}  // namespace

std::string build_id() {
  std::string id;
  // The first object dl_iterate_phdr reports is the executable itself.
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* out) {
        for (int i = 0; i < info->dlpi_phnum; ++i) {
          const ElfW(Phdr)& ph = info->dlpi_phdr[i];
          if (ph.p_type != PT_NOTE) continue;
          const std::size_t align = ph.p_align < 4 ? 4 : ph.p_align;
          const auto padded = [align](std::size_t n) { return (n + align - 1) & ~(align - 1); };
          const char* note = reinterpret_cast<const char*>(info->dlpi_addr + ph.p_vaddr);
          const char* end = note + ph.p_memsz;
          while (note + sizeof(ElfW(Nhdr)) <= end) {
            const auto* h = reinterpret_cast<const ElfW(Nhdr)*>(note);
            const char* name = note + sizeof(ElfW(Nhdr));
            const auto* desc = reinterpret_cast<const unsigned char*>(name + padded(h->n_namesz));
            if (h->n_type == NT_GNU_BUILD_ID && h->n_namesz == 4 &&
                std::memcmp(name, "GNU", 4) == 0) {
              std::string& hex = *static_cast<std::string*>(out);
              for (std::size_t k = 0; k < h->n_descsz; ++k) {
                char digits[3];
                std::snprintf(digits, sizeof digits, "%02x", desc[k]);
                hex += digits;
              }
              return 1;
            }
            note = reinterpret_cast<const char*>(desc) + padded(h->n_descsz);
          }
        }
        return 1;
      },
      &id);
  if (id.empty())
    throw CheckpointError(
        "this executable has no GNU build ID to identify it (link with --build-id)");
  return id;
}

void write_checkpoint(const std::string& path, const RenderIdentity& id, const FilmState& film) {
  TempFile tmp(path);
  {
    std::ofstream out(tmp.name(), std::ios::binary | std::ios::trunc);
    out << header(id, film.samples);
    // Absent parts (render/film_state.h FilmMomentArray) as the zeros they stand for, and the
    // positive samples' count, which the film does not store.
    for (const FilmMomentArray* moments : {&film.pixels, &film.aovs})
      for (std::size_t i = 0; i < moments->size(); ++i)
        write_moments(out, moments->at(i, film.samples));
    const RenderStats& s = film.stats;
    out.write(reinterpret_cast<const char*>(&s.seconds), sizeof s.seconds);
    out.write(reinterpret_cast<const char*>(&s.samples), sizeof s.samples);
    out.write(reinterpret_cast<const char*>(&s.rays), sizeof s.rays);
    out.write(reinterpret_cast<const char*>(&s.rejected_nonfinite), sizeof s.rejected_nonfinite);
    out.flush();
    if (!out) throw FileError(path + ": could not write the checkpoint");
  }
  tmp.commit();
}

FilmState read_checkpoint(const std::string& path, const RenderIdentity& expected) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CheckpointError(path + ": cannot open the checkpoint");
  std::string line;
  const std::string magic = std::string(kFormat) + kVersion;
  if (!std::getline(in, line) || line.compare(0, std::strlen(kFormat), kFormat) != 0)
    throw CheckpointError(path + ": not a twinray checkpoint (first line is not '" + magic + "')");
  if (line != magic)
    throw CheckpointError(path + ": a checkpoint of format version " +
                          line.substr(std::strlen(kFormat)) + ", this twinray reads version " +
                          kVersion + " only (render again without --resume)");
  // The identity lines must read exactly as this render's header would.
  std::istringstream want(header(expected, 0));
  std::getline(want, line);
  std::string want_line;
  std::uint32_t samples = 0;
  while (std::getline(want, want_line)) {
    if (!std::getline(in, line))
      throw CheckpointError(path + ": truncated header (expected '" + want_line + "')");
    const std::string key = want_line.substr(0, want_line.find(' '));
    if (key == "samples") {
      unsigned long long n = 0;
      char tail = 0;
      if (std::sscanf(line.c_str(), "samples %llu%c", &n, &tail) != 1 || n == 0 ||
          n > 0xffffffffull)
        throw CheckpointError(path + ": bad sample count line '" + line + "'");
      samples = static_cast<std::uint32_t>(n);
    } else if (line != want_line) {
      const std::string what = line.substr(0, line.find(' '));
      if (what != key) throw CheckpointError(path + ": damaged header (expected '" + key + "')");
      throw CheckpointError(path + ": a checkpoint of another render: its " + key + " is '" +
                            line.substr(key.size() + 1) + "', this render's is '" +
                            want_line.substr(key.size() + 1) + "'");
    }
  }
  FilmState film =
      empty_film(expected.width, expected.height, expected.aov_count, expected.pass_size);
  film.samples = samples;
  for (FilmMomentArray* moments : {&film.pixels, &film.aovs})
    for (std::size_t i = 0; i < moments->size(); ++i) {
      FilmMoments m;
      read_moments(in, m);
      if (in && m.positive.n + m.negative.n != double(samples))
        throw CheckpointError(path + ": damaged (a pixel's sample counts do not add up to " +
                              std::to_string(samples) + ")");
      moments->set(i, m);
    }
  RenderStats& s = film.stats;
  in.read(reinterpret_cast<char*>(&s.seconds), sizeof s.seconds);
  in.read(reinterpret_cast<char*>(&s.samples), sizeof s.samples);
  in.read(reinterpret_cast<char*>(&s.rays), sizeof s.rays);
  in.read(reinterpret_cast<char*>(&s.rejected_nonfinite), sizeof s.rejected_nonfinite);
  if (!in) throw CheckpointError(path + ": truncated (pixel data ends early)");
  if (in.peek() != std::char_traits<char>::eof())
    throw CheckpointError(path + ": damaged (data after the statistics)");
  return film;
}

}  // namespace tr
