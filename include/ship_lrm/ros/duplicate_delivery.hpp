// Messages that roscpp delivers twice. Inside one process roscpp links a topic twice when one thread
// advertises it while another subscribes to it: TopicManager::registerSubscriber finds the new
// publication and adds an intraprocess link, and TopicManager::advertise, which waited for the
// subscription lock, then finds the new subscription and adds a second (ros_comm,
// clients/roscpp/src/libros/topic_manager.cpp). Every message published on the topic then reaches
// the subscriber twice, both copies queued by the same publish, so the copy comes right after its
// original. The nodelets do exactly that: the LrmSolver subscribes rotor/forces on its own thread
// while the FlightModel advertises it (2026-12-04: the solver served every request twice, and its
// fluid ran twice as far as the flight model; docs/design.md, "Requests delivered twice").
#pragma once

namespace ship_lrm::ros_layer {

// True when `m` is `last` again: every field equal but the header's seq, which a publisher numbers
// at each publish (a message sent again by hand differs only there). M: a message with a header.
template <class M>
bool same_message_again(const M& m, const M& last) {
  if (m.header.stamp != last.header.stamp) return false;  // the usual case, without a copy
  M c = m;
  c.header.seq = last.header.seq;
  return c == last;
}

}  // namespace ship_lrm::ros_layer
