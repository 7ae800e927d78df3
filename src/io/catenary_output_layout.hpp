#pragma once
// What the catenary builder made, as both result files store it (the static result and the
// time series) when the scene has a `catenary`: each dropper's place, design height and
// unstretched length with the ids of its nodes and element, the registrations and the
// supports, so that users can attach loads, masses and probes, and read a dropper's force,
// without decoding the numbering. docs/output.md ("Catenary") documents them.
namespace catena::io::catenary_layout {

inline constexpr const char* group = "/catenary";
inline constexpr const char* droppers_group = "/catenary/droppers";
// Per dropper (n_droppers,), in x order:
inline constexpr const char* dropper_span = "/catenary/droppers/span";  // int32, 1-based
inline constexpr const char* dropper_number =
    "/catenary/droppers/number";                                  // int32, 1-based in span
inline constexpr const char* dropper_x = "/catenary/droppers/x";  // float64, m
// int64 node ids: the contact-wire node it pulls, and the node it hangs from.
inline constexpr const char* dropper_contact_node_id = "/catenary/droppers/contact_node_id";
inline constexpr const char* dropper_upper_node_id = "/catenary/droppers/upper_node_id";
// int32: 0 when it hangs from the messenger, k when from stitch wire k (1-based, x order).
inline constexpr const char* dropper_upper_wire = "/catenary/droppers/upper_wire";
// int64 element id: the bar, or the lowest cable element (whose axial force is the pull on
// the contact wire).
inline constexpr const char* dropper_element_id = "/catenary/droppers/element_id";
inline constexpr const char* dropper_design_height = "/catenary/droppers/design_height";  // m
inline constexpr const char* dropper_unstretched_length =
    "/catenary/droppers/unstretched_length";  // m, as shape finding set it

inline constexpr const char* supports_group = "/catenary/supports";
// Per support (n_spans + 1,), in x order:
inline constexpr const char* support_x = "/catenary/supports/x";  // float64, m
// int64 node ids of the contact wire and the messenger held at each support (with stagger
// a wire has two nodes at an intermediate support, joined by a spring: the one that ends
// the span before).
inline constexpr const char* support_contact_node_id = "/catenary/supports/contact_node_id";
inline constexpr const char* support_messenger_node_id = "/catenary/supports/messenger_node_id";

}  // namespace catena::io::catenary_layout
