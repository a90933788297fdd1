// SPDX-License-Identifier: MIT
// satviz app: the queue of key events between the window system and Dear ImGui 1.86, which reads the keys' state
// once per frame (io.KeysDown): a key pressed and released between two frames, a short tap or a frame that took
// long, would never be seen down; the queue below keeps every press down for one frame at least. No GLFW here.
#pragma once

#include <cstddef>
#include <vector>

namespace satviz
{

/// One key event as the window system reports it.
struct KeyEvent
{
    int key = 0;        ///< key code
    int scancode = 0;   ///< the system's scancode
    bool press = false; ///< pressed (true) or released (false); repeats are not queued
    int mods = 0;       ///< modifier bits
};

/// Key events kept until a frame can see them: each frame takes them in order until the first release after a
/// press, which waits for the next frame with everything after it. Every press is then seen down for one frame at
/// least, with the modifiers held at that moment: xdotool's ctrl+q releases ctrl before q.
class KeyQueue
{
  public:
    /// Adds an event as it arrives.
    void Push(const KeyEvent& event) { m_events.push_back(event); }
    /// True while events wait for a frame.
    bool Waiting() const { return !m_events.empty(); }
    /// Hands `deliver` the events of this frame, in order, and keeps the rest.
    template <typename Deliver>
    void TakeFrame(Deliver&& deliver)
    {
        bool pressed = false;
        size_t taken = 0;
        for (; taken < m_events.size(); ++taken)
        {
            const KeyEvent& event = m_events[taken];
            if (!event.press && pressed)
            {
                break;
            }
            pressed = pressed || event.press;
            deliver(event);
        }
        m_events.erase(m_events.begin(), m_events.begin() + static_cast<std::ptrdiff_t>(taken));
    }

  private:
    std::vector<KeyEvent> m_events;
};

} // namespace satviz
