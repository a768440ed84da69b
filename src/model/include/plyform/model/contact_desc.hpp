#pragma once

#include <array>
#include <string>
#include <vector>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// The *CONTACT_ keywords plyform reads (all with the _ID option).
enum class ContactKind {
  one_way_surface_to_surface,            ///< *CONTACT_ONE_WAY_SURFACE_TO_SURFACE
  surface_to_surface,                    ///< *CONTACT_SURFACE_TO_SURFACE (two-way)
  forming_one_way_surface_to_surface,    ///< *CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE
  automatic_surface_to_surface,          ///< *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE (two-way)
  automatic_one_way_surface_to_surface,  ///< *CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE
  automatic_single_surface,              ///< *CONTACT_AUTOMATIC_SINGLE_SURFACE (SSID only)
  tied_nodes_to_surface,                 ///< *CONTACT_TIED_NODES_TO_SURFACE(_OFFSET)
  tied_shell_edge_to_surface,            ///< *CONTACT_TIED_SHELL_EDGE_TO_SURFACE(_OFFSET)
};

/// A tied contact: the slave nodes follow the master surface (a constraint, not a contact
/// pass; setup::build makes core::TiedInterface of it).
inline bool is_tied(ContactKind k) {
  return k == ContactKind::tied_nodes_to_surface || k == ContactKind::tied_shell_edge_to_surface;
}

/// What SSID / MSID name (LS-DYNA's SSTYP / MSTYP codes).
enum class ContactSideType : int {
  segment_set = 0,  ///< *SET_SEGMENT
  part_set = 2,     ///< *SET_PART_LIST
  part = 3,         ///< one *PART
  node_set = 4,     ///< *SET_NODE_LIST (slave side only)
  all_parts = 5,    ///< every part (single-surface contacts only)
};

/// One *CONTACT_..._SURFACE_TO_SURFACE (_ID) keyword: cards 1-3 and optional card A.
struct ContactDesc {
  ContactKind kind = ContactKind::one_way_surface_to_surface;
  std::string keyword;  ///< the keyword as written (upper case), for messages
  int id = 0;           ///< CID of the _ID option (0 without it)
  std::string heading;  ///< HEADING of the _ID option
  bool offset = false;  ///< _OFFSET of a tied contact
  // Card 1
  int ssid = 0;  ///< SSID: slave side (set or part id)
  int msid = 0;  ///< MSID: master side
  ContactSideType sstyp = ContactSideType::segment_set;
  ContactSideType mstyp = ContactSideType::segment_set;
  int spr = 0;  ///< SPR: slave side in the interface force file (kept as written)
  int mpr = 0;  ///< MPR
  // Card 2
  double fs = 0.0;      ///< FS: static friction coefficient
  double fd = 0.0;      ///< FD: dynamic friction coefficient
  double dc = 0.0;      ///< DC: exponential decay coefficient [time/length]
  double vc = 0.0;      ///< VC: viscous friction limit [stress] (0: none)
  double vdc = 0.0;     ///< VDC: normal viscous damping, percent of critical
  double birth = 0.0;   ///< BT: birth time
  double death = 1e20;  ///< DT: death time (a written 0 is 1e20, as LS-DYNA)
  // Card 3
  double sfs = 1.0;   ///< SFS: slave penalty scale factor
  double sfm = 1.0;   ///< SFM: master penalty scale factor
  double sst = 0.0;   ///< SST: slave contact thickness (0: the shell thickness)
  double mst = 0.0;   ///< MST: master contact thickness (0: the shell thickness)
  double sfst = 1.0;  ///< SFST: scale factor of the slave thickness
  double sfmt = 1.0;  ///< SFMT: scale factor of the master thickness
  double fsf = 1.0;   ///< FSF: friction coefficient scale factor
  double vsf = 1.0;   ///< VSF: viscous friction scale factor
  // Optional card A
  int soft = 0;           ///< SOFT: 0 penalty from the material, 1 from masses and time step
  double sofscl = 0.1;    ///< SOFSCL: scale factor of the SOFT = 1 stiffness
  double maxpar = 1.025;  ///< MAXPAR: parametric extension of a segment for the projection
  int bsort = 0;          ///< BSORT: cycles between bucket sorts (0: automatic)
  int ignore = 0;         ///< IGNORE (optional card C): 0 *CONTROL_CONTACT's, 1-2 tracked
  // The tiebreak card (the _TIEBREAK option, right after card 3): docs/contact.md.
  bool tiebreak = false;
  int tiebreak_option = 0;       ///< OPTION: 1-4 (the others are rejected by the reader)
  double nfls = 0.0;             ///< NFLS: normal failure stress (tension)
  double sfls = 0.0;             ///< SFLS: shear failure stress (OPTION 4, PARAM 1: friction limit)
  double param = 0.0;            ///< PARAM: OPTION 4 only, 1 = SFLS is a frictional stress limit
  SourceLocation tiebreak_card;  ///< the line of the tiebreak card
  // Thermal card (the _THERMAL option): heat across the interface (docs/thermal.md).
  bool thermal = false;
  double k = 0.0;        ///< K: conductivity of the gap medium (h = K / gap across an open gap)
  double frad = 0.0;     ///< FRAD: radiation factor across an open gap
  double h0 = 0.0;       ///< H0: conductance of a closed gap (< 0: -H0 a curve against pressure)
  double lmin = 0.0;     ///< LMIN: gaps up to LMIN are closed
  double lmax = 0.0;     ///< LMAX: no heat across gaps beyond LMAX
  double ftosa = 0.5;    ///< FTOSA: share of the friction heat to the slave side
  int bc_flg = 0;        ///< BC_FLG: 1 = the heat boundaries are off where the sides touch
  int algo = 0;          ///< ALGO: 0 two-way, 1 one-way (the master's temperature unchanged)
  SourceLocation where;  ///< the keyword line
  SourceLocation card1;  ///< the line of card 1 (SSID ...)
};

/// *SET_SEGMENT (_TITLE): quadrilaterals (N3 = N4 for a triangle) given by node ids.
struct SetSegmentDesc {
  int id = 0;                                ///< SID
  std::string title;                         ///< from the _TITLE option
  std::vector<std::array<int, 4>> segments;  ///< N1..N4 of each segment
  std::vector<SourceLocation> segments_where;
  SourceLocation where;  ///< the line of card 1 (SID ...)
};

/// *CONTROL_CONTACT: the fields plyform implements; the reader rejects others not at their
/// defaults.
struct ControlContactDesc {
  double slsfac = 0.1;  ///< SLSFAC: penalty scale factor of every contact (a written 0 is 0.1)
  int shlthk = 0;       ///< SHLTHK: shell thickness in non-automatic contacts (see docs)
  /// PENOPT: 1 min(slave, master), 2 master, 3 slave stiffness; 0 when the deck leaves it
  /// blank (1 for a plain contact, a cohesive interface's own rule: docs/contact.md)
  int penopt = 0;
  int thkchg = 0;      ///< THKCHG: 1 = offsets follow the current shell thickness
  int nsbcs = 0;       ///< NSBCS: cycles between bucket sorts (0: automatic)
  int frceng = 0;      ///< FRCENG: 1 = friction heats the _THERMAL contacts' sides (SOLN 2)
  int ignore = 0;      ///< IGNORE: initial penetrations 0 pushed out, 1 tracked, 2 tracked+listed
  double sfric = 0.0;  ///< SFRIC: default static friction (contacts with FS = 0)
  double dfric = 0.0;  ///< DFRIC: default dynamic friction
  double edc = 0.0;    ///< EDC: default decay coefficient
  double vfc = 0.0;    ///< VFC: default viscous friction limit
  SourceLocation where;
};

}  // namespace plyform::model
