// A generated message type to bytes and back (CDR, as on the wire, without the encapsulation
// header): for the input journal (journal.hpp), which keeps messages to hand them to the same
// handlers again.
//
//   const std::string bytes = to_cdr(clock);
//   const msgs::Clock again = from_cdr<msgs::Clock>(bytes);  // throws on bytes that do not decode
#pragma once

#include <stdexcept>
#include <string>

#include <fastcdr/Cdr.h>
#include <fastcdr/FastBuffer.h>
#include <fastcdr/exceptions/Exception.h>

namespace swarm::comm {

template <class T>
std::string to_cdr(const T& msg) {
  std::string buf(T::getCdrSerializedSize(msg) + 8, '\0');
  eprosima::fastcdr::FastBuffer fb(buf.data(), buf.size());
  eprosima::fastcdr::Cdr cdr(fb, eprosima::fastcdr::Cdr::DEFAULT_ENDIAN, eprosima::fastcdr::Cdr::DDS_CDR);
  msg.serialize(cdr);
  buf.resize(cdr.getSerializedDataLength());
  return buf;
}

template <class T>
T from_cdr(const std::string& bytes) {
  std::string copy = bytes;  // FastBuffer reads through a non-const pointer
  eprosima::fastcdr::FastBuffer fb(copy.data(), copy.size());
  eprosima::fastcdr::Cdr cdr(fb, eprosima::fastcdr::Cdr::DEFAULT_ENDIAN, eprosima::fastcdr::Cdr::DDS_CDR);
  T msg;
  try {
    msg.deserialize(cdr);
  } catch (const eprosima::fastcdr::exception::Exception& e) {
    throw std::runtime_error(std::string("bytes that do not decode: ") + e.what());
  }
  return msg;
}

}  // namespace swarm::comm
