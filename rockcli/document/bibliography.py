"""The works a report cites, in full (its bibliography): each once, in the order a reader
meets them, as a reviewer expects to find them — authors, title, journal or issuer, volume,
pages, year.

The texts are bibliographic data, the same in every language; the report's words add only the
heading and what each work is to rock (messages ``[bib]``).
"""

from __future__ import annotations

#: (key, reference): the key names the work in the report's words (``bib.role_<key>``, its
#: role, when it has one).
REFERENCES: tuple[tuple[str, str], ...] = (
    ("paper", "L. Giresini, M. Fragiacomo, P. B. Lourenço, Comparison between rocking analysis "
     "and kinematic analysis for the dynamic out-of-plane behavior of masonry walls, "
     "Earthquake Engineering & Structural Dynamics 44(13), 2359–2376, 2015."),
    ("housner", "G. W. Housner, The behavior of inverted pendulum structures during "
     "earthquakes, Bulletin of the Seismological Society of America 53(2), 403–417, 1963."),
    ("makris", "N. Makris, Y. S. Roussos, Rocking response of rigid blocks under near-source "
     "ground motions, Géotechnique 50(3), 243–262, 2000."),
    ("sorrentino", "L. Sorrentino, R. Masiani, M. C. Griffith, The vertical spanning strip wall "
     "as a coupled rocking rigid body assembly, Structural Engineering and Mechanics 29(4), "
     "433–453, 2008."),
    ("doherty", "K. Doherty, M. C. Griffith, N. Lam, J. Wilson, Displacement-based seismic "
     "analysis for out-of-plane bending of unreinforced masonry walls, Earthquake Engineering "
     "& Structural Dynamics 31(4), 833–850, 2002."),
    ("dayala", "D. D'Ayala, E. Speranza, Definition of collapse mechanisms and seismic "
     "vulnerability of historic masonry buildings, Earthquake Spectra 19(3), 479–509, 2003."),
    ("ntc2018", "Ministero delle Infrastrutture e dei Trasporti, Aggiornamento delle «Norme "
     "tecniche per le costruzioni» (NTC 2018), D.M. 17 gennaio 2018, G.U. n. 42 del 20 febbraio "
     "2018, S.O. n. 8."),
    ("circ2019", "Ministero delle Infrastrutture e dei Trasporti, Circolare 21 gennaio 2019 n. 7 "
     "C.S.LL.PP., Istruzioni per l'applicazione dell'«Aggiornamento delle Norme tecniche per le "
     "costruzioni» di cui al D.M. 17 gennaio 2018, G.U. n. 35 dell'11 febbraio 2019, S.O. n. 5."),
    ("ntc2008", "Ministero delle Infrastrutture, Norme tecniche per le costruzioni (NTC 2008), "
     "D.M. 14 gennaio 2008, G.U. n. 29 del 4 febbraio 2008, S.O. n. 30."),
    ("circ2009", "Ministero delle Infrastrutture e dei Trasporti, Circolare 2 febbraio 2009 n. "
     "617 C.S.LL.PP., Istruzioni per l'applicazione delle «Nuove norme tecniche per le "
     "costruzioni» di cui al D.M. 14 gennaio 2008, G.U. n. 47 del 26 febbraio 2009, S.O. n. 27."),
)  # fmt: skip
