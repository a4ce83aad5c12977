// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Tests that a FIFO is refused without being opened: should a reader open it after all, a
// writer opening it later lets that open return, so the test fails instead of hanging.

#ifndef QM2_TEST_FIFO_H
#define QM2_TEST_FIFO_H

#include <chrono>
#include <string>
#include <thread>

#include <fcntl.h>
#include <unistd.h>

namespace qm2_test {

/// opens the FIFO `path` for writing, and closes it, `delay` from now, in the background
inline void open_fifo_for_writing_after(const std::string& path, std::chrono::seconds delay)
{
  std::thread([path, delay] {
    std::this_thread::sleep_for(delay);
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK);
    if(fd >= 0) ::close(fd);
  }).detach();
}

} // namespace qm2_test

#endif // QM2_TEST_FIFO_H
