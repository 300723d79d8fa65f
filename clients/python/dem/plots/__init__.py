"""The seeds' figures with matplotlib, each a function that draws on given
axes (or a new headless figure) and writes a PNG when given a path:

- plot_stress_settlement, LiveStressSettlement: plate stress against
  settlement, live while a run goes on or as PNG files (Miyata Figs. 26, 32);
- plot_force_distribution: P(f) of the normalised contact force on a plate
  with the q-model (eq. 62) and Mueth's fit (eq. 61) (Miyata Fig. 35);
- plot_force_chains: contact forces as rectangles (Cundall & Strack Figs.
  5(b), 11);
- plot_contact_force_history: the nine-disc force at contact C against
  cycles (Cundall & Strack Figs. 6, 7, 9);
- plot_psi2_against_psi1: the oblique impact sweep (Randall Fig. 5.10);
- plot_stress_settlement_family, plot_final_measure: a parameter sweep's
  stress-settlement curves and final measures (dem.sweep.Results);
- plot_rose, plot_obliquity_histogram, plot_shear_series,
  plot_stress_path, plot_discharge, plot_velocity_field: Randall's
  chapter 6 (granular.py); plot_contact_forces, plot_porosity_profile,
  plot_circle_series: its centripetal compaction, Figs. 6.4-6.8
  (randall_centripetal.py); plot_contact_stress_histograms,
  plot_size_contacts: its contact stresses, Figs. 6.42-6.43, and each
  size's contacts (randall_contact_stresses.py); plot_contact_lattice:
  its Fig. 6.35 (randall_lattice.py);
- draw_miyata_directory: Miyata et al.'s Figs. 26-37 from a run's plate
  loading analyses (miyata.py, over miyata_loading, miyata_assembly,
  miyata_plates and miyata_moment).

Figures are drawn on matplotlib's Agg canvas (figure.py), so nothing here
needs a display.
"""

from .contact_history import plot_contact_force_history
from .figure import new_axes, save_png
from .force_chains import plot_force_chains
from .force_distribution import plot_force_distribution
from .granular import (plot_discharge, plot_obliquity_histogram, plot_rose, plot_shear_series, plot_stress_path,
                       plot_velocity_field)
from .miyata import draw_miyata_directory
from .oblique_impact import plot_psi2_against_psi1
from .randall_lattice import plot_contact_lattice
from .randall_contact_stresses import plot_contact_stress_histograms, plot_size_contacts
from .randall_centripetal import (draw_centripetal_directory, plot_circle_series, plot_contact_forces,
                                  plot_porosity_profile)
from .stress_settlement import LiveStressSettlement, StressSettlementSeries, plot_stress_settlement
from .sweep import plot_final_measure, plot_stress_settlement_family
from .randall import draw_randall_directory

__all__ = [
    "LiveStressSettlement",
    "StressSettlementSeries",
    "draw_centripetal_directory",
    "draw_miyata_directory",
    "draw_randall_directory",
    "new_axes",
    "plot_circle_series",
    "plot_contact_forces",
    "plot_contact_lattice",
    "plot_contact_stress_histograms",
    "plot_discharge",
    "plot_obliquity_histogram",
    "plot_porosity_profile",
    "plot_rose",
    "plot_shear_series",
    "plot_size_contacts",
    "plot_stress_path",
    "plot_velocity_field",
    "plot_contact_force_history",
    "plot_force_chains",
    "plot_final_measure",
    "plot_force_distribution",
    "plot_psi2_against_psi1",
    "plot_stress_settlement",
    "plot_stress_settlement_family",
    "save_png",
]
