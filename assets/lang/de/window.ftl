# Die Wörter des Fensters auf Deutsch: Leisten, obere Leiste, Reiter, der Startbildschirm.
# Jede andere Sprache hat dieselben Nachrichten mit denselben $-Werten.

this-language = Deutsch
language-now = Sprache: { this-language }

## Die obere Leiste
scene-untitled = Sandkasten
scene-edited-mark = (geändert)
state-rewound = ZURÜCKGESPULT
state-paused = PAUSIERT
state-running = LÄUFT
state-stalled = STECKT FEST
rewound-line = aufgezeichnet: { $oldest } bis { $newest } s; Leertaste setzt fort
momentum-hover = Gesamtimpuls der Scheiben
momentum-walls-push = p = { $momentum } (Wände stoßen)
momentum-walls-push-hover = Wände stoßen: Der Impuls der Scheiben ändert sich nur an den Wänden; bei Stößen zwischen Scheiben bleibt er erhalten
energy-with-turning = Ekin { $moving } + Drehung { $turning } = { $total }
energy-with-turning-hover = Bewegungsenergie ½·m·v² plus Rotationsenergie ½·I·ω² mit I = ½·m·r², summiert über alle Scheiben
energy-line = Ekin = { $energy }
energy-hover = kinetische Energie: die Bewegungsenergie ½·m·v², summiert über alle Scheiben
count-hover = Stöße zwischen zwei Scheiben und Stöße einer Scheibe an eine Wand, getrennt gezählt
com-view-line = Schwerpunktsystem: p = { $momentum }, Ekin = { $energy }
energy-with-height = Ekin + Epot = { $energy }
energy-with-height-hover = Bewegungsenergie (und Rotationsenergie) plus Lageenergie, null an der Unterkante des Kastens
angular-momentum-hover = Drehimpuls um die Ecke (0; 0), aus Bewegung und Drehung: Stöße zwischen Scheiben erhalten ihn, Wände ändern ihn
resting-contacts = ruhende Kontakte: { $count }
resting-contacts-hover = Scheiben, die aufeinander oder an einer Wand liegen: Sie zählen nicht als Stöße
show-panels = Leisten einblenden
top-bar-more = … mehr
running-slower = läuft mit { $rate }× Echtzeit
running-slower-many = läuft mit { $rate }× Echtzeit: mit weniger Scheiben ginge es schneller
method-in-use = aktiv: { $method } / { $broad }
method-in-use-auto = aktiv: { $method } / { $broad } (auto: { $reason })

## Fenster über der Welt
recovery-title = Letzte Sitzung wiederherstellen?
recovery-waits = Die Simulation wartet auf deine Antwort.
recovery-restore = Wiederherstellen (R)
recovery-set-aside = Beiseitelegen (Esc)
help-title = Tasten und Maus
presets-title = Vorlagen
reopen-kept-hover = Der Sandkasten, den dieser Browser aufbewahrt hat, bevor der Link geöffnet wurde.
presets-press = Taste drücken oder anklicken:

## Die Leiste unter der Welt
caption-edited = Vor den Änderungen: { $caption }
caption-none = Auf freier Fläche ziehen, um eine Scheibe abzuschießen; H zeigt alle Tasten.

## Größen, wie Felder und Spalten sie nennen
quantity-mass = Masse
quantity-radius = Radius
quantity-vx = v_x
quantity-vy = v_y
quantity-x = x
quantity-y = y
quantity-speed = Tempo |v|
quantity-direction = Richtung
direction-hover = Grad ab rechts, gegen den Uhrzeigersinn: 0 rechts, 90 oben, 180 links, −90 unten

## Die Reiter der unteren Leiste
tab-totals = Bilanz
tab-collisions = Stöße
tab-discs = Scheiben
tab-speeds = Tempo
tab-momenta = Impulse

## Die Kacheln des Startbildschirms
tile-head-on = Zentraler Stoß (1D)
tile-glancing = Schiefer Stoß (2D)
tile-inelastic = Unelastisch
tile-pi-blocks = π-Klötze
tile-gas = Ein Gas
tile-free-play = { scene-untitled }
tile-head-on-blurb = Zwei Scheiben treffen sich auf einer Linie. Ist der Gesamtimpuls danach derselbe?
tile-glancing-blurb = Eine Scheibe trifft eine andere außermittig. In welche Richtungen fliegen sie?
tile-inelastic-blurb = Scheiben, die nicht voll zurückprallen. Wo bleibt die Energie?
tile-pi-blocks-blurb = Ein leichter Klotz, ein schwerer und eine Wand: Zähle die Stöße.
tile-gas-blurb = Viele Scheiben auf einmal: Wie verteilen sich ihre Geschwindigkeiten?
tile-free-play-blurb = Schieße eigene Scheiben ab und verändere alles.
lesson-wall-pause = Angehalten: Scheibe { $disc } traf die { $wall ->
    [left] linke
    [right] rechte
    [bottom] untere
   *[top] obere
} Wand, und der Stoß einer Wand ändert den Gesamtimpuls. { $key } lässt weiterlaufen.

## Der Startbildschirm
close = Schließen
start-title = Was möchtest du erkunden?
start-footer = Tab und Enter wählen eine Lektion mit der Tastatur. Esc behält die geöffnete Szene. Die Schaltfläche „Start“ in der oberen Leiste holt diese Seite zurück.

## Die Seitenleiste
controls-for = Die Regler für „{ $lesson }“.
selected-disc-numbered = Gewählte Scheibe ({ $disc })
section-more = Mehr
section-more-line = Für sich drehende Scheiben und zum Vergleichen, wie der Computer rechnet.
play = Los
pause = Pause
colour-white = weiß
colour-pink = rosa
colour-amber-outlined = bernsteinfarben, umrandet
colour-black = schwarz
colour-purple = lila
colour-brown-outlined = braun, umrandet
show-velocity = Geschwindigkeitspfeile ({ $colour })
show-velocity-hover = wo jede Scheibe in einer halben Sekunde sein wird
show-momentum = Impulspfeile ({ $colour })
show-momentum-hover = Impuls p = m·v: Masse mal Geschwindigkeit
show-delta-p = Δp nach einem Stoß ({ $colour })
show-delta-p-hover = die Impulsänderung jeder Scheibe, eine Sekunde lang nach jedem Stoß zwischen Scheiben (in Szenen mit bis zu { $most } Scheiben: in einem Gas würden die Pfeile die Scheiben verdecken)
readouts-none = keine
readouts-selected = gewählte Scheibe
readouts-all = alle Scheiben
readouts-label = Werte daneben
readouts-hover = wo sich Beschriftungen überdecken würden, bleiben einige Scheiben ohne; die Welt zeigt an, wie viele
show-center-of-mass = Schwerpunkt
show-center-of-mass-hover = der gemeinsame Schwerpunkt aller Scheiben und seine Geschwindigkeit
show-safe-palette = Farben für Farbenblinde
show-com-view = Schwerpunktsystem
show-com-view-hover = die Ansicht bewegt sich mit dem Schwerpunkt, und die Pfeile zeigen Geschwindigkeiten relativ zu ihm; das Experiment selbst ändert sich nicht

## Der Abschnitt Stöße
restitution-label = Abprall zwischen Scheiben, Stoßzahl e
restitution-scale = 1: sie prallen voll zurück, 0: sie bewegen sich längs der Stoßlinie gemeinsam weiter
restitution-hover = Wie viel ihrer Annäherungsgeschwindigkeit zwei Scheiben beim Auseinanderfliegen behalten, längs der Linie durch ihre Mittelpunkte: 1 alles, 0 nichts (die Bewegung quer dazu bleibt erhalten)
wall-restitution-label = Abprall an den Wänden, Stoßzahl e
wall-restitution-hover = Wie viel ihrer Geschwindigkeit auf eine Wand zu eine Scheibe behält, wenn sie sich wieder von ihr entfernt: 1 alles, 0 nichts
gravity-label = Schwerkraft, nach unten gerichtet
gravity-hover = wie stark die Scheiben nach unten gezogen werden; auf der Erde { $gravity } m/s²
edges-label = Ränder
edges-box = Kasten
edges-open = offen
edges-periodic = periodisch
edges-hover = Was die Seiten des Kastens tun: Kasten – Wände, an denen die Scheiben abprallen; offen – keine Wände (die Scheiben fliegen davon); periodisch – eine Scheibe, die auf einer Seite hinausfliegt, kommt auf der gegenüberliegenden wieder herein
time-scale-label = Zeitfaktor
time-scale-hover = simulierte Sekunden pro echter Sekunde: unter 1 ist Zeitlupe
roughness-hover = Wie stark die sich berührenden Ränder bei einem Stoß aneinander haften, sodass Scheiben sich zu drehen beginnen oder damit aufhören: −1 glatt (keine Haftung, keine Drehung übertragen), 0 ihr Gleiten stoppt, 1 vollkommen rau (das Gleiten kehrt sich um, und es geht keine Energie verloren)
roughness-label = Haftung zwischen Scheiben, Rauigkeit β (−1 glatt … 1 rau)
wall-roughness-label = Haftung an den Wänden, Rauigkeit β
friction-on-label = Reibungszahl μ begrenzt die Haftung
friction-hover = Reibung: Die seitliche Kraft an der Berührstelle ist höchstens μ-mal so groß wie die Normalkraft, schnelles Gleiten wird also nur gebremst; außerdem reiben Scheiben, die aufeinander liegen, aneinander. Aus: keine Grenze.
friction-label = Reibungszahl μ

## Neue Scheiben und die gewählte Scheibe
new-discs-line = Auf freier Fläche ziehen, um eine abzuschießen.
size-follows-mass = Größe folgt der Masse (gleiche Dichte)
size-follows-mass-hover = eine Scheibe mit 1 kg hat 0,4 m Radius; der Radius wächst mit √m, für neue Scheiben und bei Änderungen der Masse
radius-from-mass = Radius { $radius } (aus der Masse)
radius-label = Radius
mass-label = Masse
new-mass-hover = Neue Scheiben wiegen 0,01 bis 100 kg: Ein Schieberegler braucht zwei Enden, und diese reichen für Massenverhältnisse bis 10 000 zu 1. Eine Scheibe in der Box nimmt jede Masse: Tippen Sie sie im Reiter Scheiben oder unter Gewählte Scheibe ein
selected-none = Keine: eine Scheibe anklicken, um sie auszuwählen.
apply = Übernehmen
apply-hover = Enter in einem Feld

## Die Abschnitte Szene und Ansicht
preset-label = Vorlage
preset-choose = Vorlage öffnen…
scene-drop = Szenendatei öffnen: auf die Seite ziehen und dort ablegen.
scene-file-label = Szenendatei:
scene-file-hint = z. B. assets/scenes/preset-8-gas.toml
scene-name-label = Name:
scene-name-hover = Der Name der Szene: Er steht oben im Fenster und benennt die Dateien, unter denen sie gespeichert wird. Eintippen und Enter drücken.
open = Öffnen
open-hover = Enter im Feld
share = Link teilen
share-hover = schreibt diese Szene in die Adresse der Seite, um sie als Link zu verschicken
saves-download = Gespeicherte Szenen, Exporte und Screenshots werden als Dateien heruntergeladen.
saves-go-to = Gespeichert wird in { $folder }/
ui-scale-label = Größe von Text und Bedienelementen
theme-light = Helles Design
theme-dark = Dunkles Design
theme-hover = in einem hellen Raum ist das helle besser
language-label = Sprache
language-hover = die Sprache des Fensters; Zahlen richten sich danach (2,5 statt 2.5)

## Details (unter Mehr)
method-label = Verfahren
method-hover = Wie der Computer die Stöße berechnet: auto wählt selbst; exact findet jeden Stoß genau in seinem Augenblick; die anderen rechnen in kleinen festen Zeitschritten und korrigieren Überlappungen
broad-phase-label = Grobphase
broad-phase-hover = Wie der Computer herausfindet, welche Scheiben nahe beieinander sind, bevor er sie genau prüft: Das ändert nur die Rechengeschwindigkeit, nicht das Ergebnis
substeps-label = Teilschritte
substeps-hover = In wie viele kleinere Schritte jeder Zeitschritt zerlegt wird: mehr ist genauer und langsamer
dt-line = Zeitschritt dt = { $dt }
dt-hover = wie viel simulierte Zeit ein Rechenschritt des Computers abdeckt
step-time-line = Schrittdauer { $time } (Median), { $steps } Schritte im letzten Bild
fps-line = { $fps } Bilder pro Sekunde
sim-rate-line = simulierte Sekunden pro echter Sekunde: { $rate }
page-title = Impulse: Stöße von Scheiben

## Der Reiter Bilanz
symbol-ke = Ekin
totals-energy = Energie
totals-kinetic-energy = kinetische Energie
totals-momentum = Impuls
totals-angular-momentum = Drehimpuls L
totals-change = Änderung seit t = { $since }: { $p_name } { $momentum }, { $l_name } { $angular }, { $e_name } { $energy }
totals-change-line = Änderung seit t = { $since }: { $p_name } { $momentum }, { $e_name } { $energy }
totals-change-wrapping = Änderung seit t = { $since }: { $p_name } { $momentum }, { $e_name } { $energy }; { $l_name } bleibt nicht erhalten, wenn Scheiben über den Rand springen
totals-none = Noch keine Aufzeichnung: Simulation laufen lassen.
totals-rotational-ke = Rotationsenergie
totals-ke-sum = Ekin + Rotationsenergie
totals-sum = Summe
totals-hover = p: Impuls, Masse mal Geschwindigkeit, summiert über alle Scheiben. L: Drehimpuls, wie sehr die Scheiben um die linke untere Ecke des Kastens (0; 0) kreisen und sich drehen. Stöße zwischen Scheiben erhalten beide; die Kraftstöße der Wände ändern sie (gestrichelte Linien zeigen, wo). E: die Bewegungsenergie (Ekin), bei sich drehenden Scheiben auch die Rotationsenergie.
totals-hover-wrapping = In dieser Welt hängen die Ränder zusammen: Eine Scheibe, die auf einer Seite hinausfliegt, kommt auf der anderen wieder herein. Ihr Impuls bleibt gleich, aber ihre Lage bezüglich (0; 0) springt, also springt auch L; das ist kein Fehler der Stöße.
totals-walls-push = Wände stoßen
axis-time = Zeit (s)
axis-energy = Energie (J)

## Der Reiter Stöße (das Stoßprotokoll)
ledger-pair = Scheiben { $a } und { $b }
ledger-wall = Scheibe { $disc } und die { $wall ->
    [left] linke
    [right] rechte
    [bottom] untere
   *[top] obere
} Wand
ledger-empty = Noch keine. „Nächster Stoß“ (J) lässt die Simulation bis zum nächsten Stoß laufen, zwischen Scheiben oder mit einer Wand, und hält im Augenblick des Aufpralls an.
ledger-last = { $count ->
    [one] Der letzte Stoß
   *[other] Die letzten { $count }, neueste zuerst
}
ledger-time-hover = wann es geschah
ledger-what = was
ledger-what-hover = welche Scheiben, oder welche Scheibe und Wand
ledger-dp-hover = die Änderung des Gesamtimpulses der beteiligten Scheiben: null zwischen Scheiben, an einer Wand der Kraftstoß der Wand
ledger-dke-hover = die Änderung ihrer kinetischen Energie, der Bewegungsenergie: null bei einem elastischen Stoß, kleiner als null, wenn etwas verloren geht
ledger-newest = { $who }, { $when }
ledger-disc-p = Scheibe { $disc }: p (kg·m/s)
ledger-disc-ke = Scheibe { $disc }: { $ke } (J)
ledger-disc-v = Scheibe { $disc }: v { $part } (m/s)
ledger-both-p = beide Scheiben: p (kg·m/s)
ledger-both-ke = beide Scheiben: { $ke } (J)
ledger-along-impact = längs der Stoßlinie
ledger-across-impact = quer dazu
ledger-away-from-wall = von der Wand weg
ledger-along-wall = längs der Wand
ledger-wall-push = Kraftstoß der Wand, Δp (kg·m/s)
ledger-before = vorher
ledger-after = nachher
ledger-detail-hover = Die Stoßlinie verläuft im Augenblick der Berührung durch die Mittelpunkte der beiden Scheiben (oder von der Wand zur Scheibe); bei einem glatten Stoß ändert sich nur die Geschwindigkeit längs dieser Linie. Längs der Linie zeigt Plus von der zuerst genannten Scheibe zur anderen (an einer Wand von der Wand weg).

## Der Reiter Scheiben
table-spin = Drehung ω
    (rad/s)
table-spin-hover = wie schnell sich die Scheibe dreht: Radiant pro Sekunde, gegen den Uhrzeigersinn positiv
table-rotational-ke-hover = die Energie ihrer Drehung, ½·I·ω² mit I = ½·m·r²
table-angular-momentum-hover = Drehimpuls, wie sehr die Scheibe um die linke untere Ecke des Kastens (0; 0) kreist und sich dreht: m·(x·v_y − y·v_x) aus ihrer Bewegung plus I·ω aus ihrer Drehung
table-disc = Scheibe
table-line = Eine Masse oder Geschwindigkeit anklicken, um sie zu ändern; Enter übernimmt, Esc bricht ab.
table-no-discs = Keine Scheiben: auf freier Fläche ziehen, um eine abzuschießen.

## Die Reiterzeile und der Reiter Impulse
dock-hide = Ausblenden
dock-show = Einblenden
dock-no-room = hier ist kein Platz: L blendet die Seitenleiste aus
dock-no-room-drawer = bei dieser Schriftgröße ist hier kein Platz: { $key } ändert sie
momenta-no-discs = Keine Scheiben.
momenta-too-many = Summe: { $total }. Zu viele Scheiben ({ $count }), um für jede einen Pfeil zu zeichnen; das Diagramm zeichnet bis zu { $most }.
momenta-line = Summe (dick): { $total }, dazu der Impuls jeder Scheibe in ihrer Farbe, Pfeil an Pfeil gehängt
momenta-hover = { $line }; p_x und p_y sind im selben Maßstab gezeichnet, die Winkel stimmen also
disc-numbered = Scheibe { $disc }
readout-disc = { $disc }:

## Der Reiter Tempo
speeds-axis-rim = Geschwindigkeit, Randgeschwindigkeit (m/s)
speeds-axis = Geschwindigkeit (m/s)
speeds-name = Geschwindigkeiten |v|
speeds-discs = Scheiben
speeds-count = Scheiben je Balken
# Hovering a bar: how many discs it counts, and its speeds.
speeds-bar = { $count ->
    [one] eine Scheibe
   *[other] { $count } Scheiben
} von { $low } bis { $high } m/s
maxwell-boltzmann = Maxwell–Boltzmann
rim-speeds = Randgeschwindigkeiten |ω|·r
rim-speeds-equal = Randgeschwindigkeiten bei gleicher Verteilung
speeds-too-few = Zu wenige bewegte Scheiben für eine Verteilung: Vorlage 8 ausprobieren, ein Gas.
speeds-line = Balken: wie viele Scheiben sich mit welcher Geschwindigkeit bewegen. Kurve: wie sich ein Gas einpendelt (Maxwell–Boltzmann).
speeds-line-few = Balken: wie viele Scheiben sich mit welcher Geschwindigkeit bewegen. Die Kurve eines Gases (Maxwell–Boltzmann) erscheint ab { $n } Scheiben: Vorlage 8 ausprobieren.
speeds-hover = { $line }
    Die Kurve zeigt, wo die Geschwindigkeiten landen, wenn Stöße die Energie zufällig verteilt haben, für Scheiben mit im Mittel so viel Energie: kT = Ekin/N = { $kt } (die Temperatur, als Energie pro Scheibe).
speeds-rim-meaning = Balken: wie viele Scheiben sich mit welcher Geschwindigkeit bewegen (oder ihren Rand drehen). Kurven: wo sie sich einpendeln, wenn die Energie gleichmäßig verteilt ist, bei der Temperatur kT = Ekin/N = { $kt }: Maxwell–Boltzmann für die Geschwindigkeiten (durchgezogen) und für die Randgeschwindigkeiten (gestrichelt).
rim-speeds-hover = Wie schnell sich der Rand jeder Scheibe bei ihrer Drehung bewegt: ihre Winkelgeschwindigkeit ω mal ihr Radius r.
    { $meaning }
shares-energy = Energie:
shares-energy-hover = der Anteil der Energie (%) in Bewegung und in Drehung
shares-moving = Bewegung
shares-turning = Drehung
shares-one-third = ein Drittel
shares-one-third-hover = Gleichmäßig verteilt auf die drei Arten, wie eine Scheibe Energie speichert (Bewegung längs x, längs y, Drehung), bekommt die Drehung ein Drittel
shares-moving-ke = Bewegung (Ekin)
shares-turning-ke = Drehung (Rotationsenergie)

## In der Welt
readout-spin = Drehung ω = { $spin }   Erot = { $energy }
readout-angular-momentum = Drehimpuls um (0; 0): L = { $angular }
readouts-culled = { $wanted ->
    [one] kein Platz für die Werte der gewählten Scheibe (mit dem Mausrad hineinzoomen)
   *[other] Werte neben { $shown } von { $wanted } Scheiben: kein Platz für den Rest (mit dem Mausrad hineinzoomen)
}
launch-no-room = hier ist kein Platz
gas-name = Gas aus { $count } Scheiben
gas-description = { $count } gleiche Scheiben bedecken 30 % eines periodischen Kastens (--gas { $count })
tab-edge = Höhe des Reiters
tab-edge-hover = Ziehen, um den Reiter höher oder niedriger zu machen. Mit der Tastatur (mit Tab hierher): die Pfeiltasten eine Zeile, Pos1 am höchsten, Ende am niedrigsten, Enter die passende Höhe; oder Doppelklick.
