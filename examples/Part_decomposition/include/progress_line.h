// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef PART_DECOMPOSITION_TOOLS_PROGRESS_LINE_H
#define PART_DECOMPOSITION_TOOLS_PROGRESS_LINE_H

// The progress of hitops on stderr. On a terminal, one status line rewritten in place ('\r' and
// clear to the end of the line): meshes done out of the total, failed and timed out, elapsed and
// estimated time left, the current mesh and its stage; a ticker thread keeps the clock moving while
// a mesh runs, at most 10 redraws a second. Elsewhere (a log, a Slurm job) one plain line per mesh.
// Quiet: nothing but the errors. POSIX only (isatty, ioctl).

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdio>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>

#include <sys/ioctl.h>
#include <unistd.h>

namespace Part_decomposition_tools {

class Progress_line
{
public:
  enum Mode { QUIET, TERMINAL, LINES };
  typedef std::chrono::steady_clock Clock;

  // TERMINAL when stderr is one, LINES otherwise, QUIET if asked.
  static Mode mode_of_stderr(bool quiet)
  {
    if(quiet) return QUIET;
    return ::isatty(STDERR_FILENO) ? TERMINAL : LINES;
  }

  // `total`: the meshes of a batch, 0 for one mesh (its stage only, once it took `delay` seconds).
  Progress_line(Mode mode, std::size_t total, double delay = 0.)
    : m_mode(mode), m_total(total), m_delay(delay), m_start(Clock::now()), m_mesh_start(m_start)
  {
    if(m_mode == TERMINAL) m_ticker = std::thread([this] { tick(); });
  }
  ~Progress_line()
  {
    stop();
    // left by an exception: the error that follows starts a line of its own
    if(m_mode == TERMINAL && m_shown) write_line(m_total == 0 ? "\r\033[K" : "\n");
  }
  Progress_line(const Progress_line&) = delete;
  Progress_line& operator=(const Progress_line&) = delete;

  Mode mode() const { return m_mode; }

  // A mesh starts.
  void begin(const std::string& name)
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_name = name;
    m_stage.clear();
    m_mesh_start = Clock::now();
    draw(false);
  }

  // What the current mesh does now (reading, decomposing, ...).
  void stage(const std::string& stage)
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_stage = stage;
    draw(false);
  }

  // A mesh is done: status ok, skipped, failed or timeout; `detail` follows it on its line.
  void end(const std::string& status, const std::string& detail, double seconds)
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    ++m_done;
    if(status == "failed") ++m_failed;
    else if(status == "timeout") ++m_timed_out;
    if(status != "skipped")
    {
      ++m_timed;
      m_timed_seconds += seconds;
    }
    if(m_mode == LINES)
    {
      std::ostringstream line;
      line << '[' << m_done << '/' << m_total << "] " << m_name << ": " << status;
      if(!detail.empty()) line << ", " << detail;
      write_line(line.str() + '\n');
    }
    m_name.clear();
    m_stage.clear();
    draw(false);
  }

  // A line of its own (an error), above the status line; printed in every mode.
  void message(const std::string& line)
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    write_line((m_shown ? "\r\033[K" : "") + line + '\n');
    m_shown = false;
    draw(true);
  }

  // The last status line of a batch stays, the stage line of one mesh goes.
  void finish()
  {
    stop();
    std::lock_guard<std::mutex> lock(m_mutex);
    if(m_mode != TERMINAL) return;
    if(m_total > 0)
    {
      m_finished = true;
      draw(true);
      write_line("\n");
    }
    else if(m_shown)
      write_line("\r\033[K");
    m_shown = false;
  }

  // Held around fork(): the child gets no half-written line, nor a lock the ticker holds.
  std::unique_lock<std::mutex> hold() { return std::unique_lock<std::mutex>(m_mutex); }

private:
  static void write_line(const std::string& text)
  {
    for(std::size_t done = 0; done < text.size();)
    {
      const ssize_t n = ::write(STDERR_FILENO, text.data() + done, text.size() - done);
      if(n <= 0) return; // a closed or full stderr loses the progress, never the run
      done += std::size_t(n);
    }
  }

  static std::string clock_text(double seconds)
  {
    const long s = long(seconds + 0.5);
    char text[32];
    if(s >= 3600) std::snprintf(text, sizeof(text), "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else std::snprintf(text, sizeof(text), "%ld:%02ld", s / 60, s % 60);
    return text;
  }

  static std::size_t terminal_columns()
  {
    winsize w;
    if(::ioctl(STDERR_FILENO, TIOCGWINSZ, &w) == 0 && w.ws_col > 10) return w.ws_col;
    return 80;
  }

  std::string status_text(Clock::time_point now) const
  {
    std::ostringstream out;
    const double mesh_seconds = std::chrono::duration<double>(now - m_mesh_start).count();
    char seconds[32];
    std::snprintf(seconds, sizeof(seconds), "%.1f s", mesh_seconds);
    if(m_total == 0)
    {
      out << "hitops: " << m_name << ": " << m_stage << ", " << seconds;
      return out.str();
    }
    const double elapsed = std::chrono::duration<double>(now - m_start).count();
    out << '[' << m_done << '/' << m_total << "] " << m_failed << " failed, " << m_timed_out << " timed out | "
        << clock_text(elapsed);
    if(m_finished) out << " elapsed, done";
    else if(m_timed > 0)
      out << " elapsed, ~" << clock_text(m_timed_seconds / double(m_timed) * double(m_total - m_done)) << " left";
    else out << " elapsed";
    if(!m_name.empty() && !m_finished)
      out << " | " << m_name << (m_stage.empty() ? "" : " (" + m_stage + ", " + seconds + ")");
    return out.str();
  }

  // Redraws the status line (lock held): at most every 0.1 s unless forced.
  void draw(bool force)
  {
    if(m_mode != TERMINAL) return;
    const Clock::time_point now = Clock::now();
    if(m_total == 0 && (m_name.empty() || now - m_mesh_start < std::chrono::duration<double>(m_delay))) return;
    if(!force && m_shown && now - m_drawn < std::chrono::milliseconds(100)) return;
    std::string text = status_text(now);
    const std::size_t columns = terminal_columns();
    if(text.size() >= columns) text = text.substr(0, columns - 1); // a wrapped line cannot be rewritten
    write_line("\r\033[K" + text);
    m_shown = true;
    m_drawn = now;
  }

  void tick()
  {
    std::unique_lock<std::mutex> lock(m_mutex);
    while(!m_stop)
    {
      m_wake.wait_for(lock, std::chrono::milliseconds(100));
      if(!m_stop) draw(false);
    }
  }

  void stop()
  {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_stop = true;
    }
    m_wake.notify_all();
    if(m_ticker.joinable()) m_ticker.join();
  }

  const Mode m_mode;
  const std::size_t m_total;
  const double m_delay;
  const Clock::time_point m_start;
  Clock::time_point m_mesh_start, m_drawn;
  std::size_t m_done = 0, m_failed = 0, m_timed_out = 0, m_timed = 0;
  double m_timed_seconds = 0.;
  std::string m_name, m_stage;
  bool m_shown = false, m_finished = false, m_stop = false;
  std::mutex m_mutex;
  std::condition_variable m_wake;
  std::thread m_ticker;
};

} // namespace Part_decomposition_tools

#endif // PART_DECOMPOSITION_TOOLS_PROGRESS_LINE_H
