# Zugang über Tastatur, Ton und Screenreader: was das Fenster dazu sagt.

select-no-discs = Keine Scheibe zum Auswählen: Enter setzt eine in die Mitte.
selected-disc-said = Scheibe { $disc } von { $discs } gewählt: { $mass }; Geschwindigkeit { $velocity }
launched-at-centre = Scheibe { $disc } ruht in der Mitte: Bei angehaltener Simulation stellen die Pfeiltasten ihre Geschwindigkeit ein
launched-near-centre = Scheibe { $disc } ruht neben Scheibe { $beside } (die Mitte war besetzt): Bei angehaltener Simulation stellen die Pfeiltasten ihre Geschwindigkeit ein

## Der Weg über die Tastatur (Zeilen der Hilfe)
keys-focus = Tab / Umschalt+Tab
help-focus = durch die Bedienelemente gehen, in Lesereihenfolge; Leertaste oder Enter betätigt eines, die Pfeiltasten verschieben einen Schieberegler, wählen in einer Auswahlliste oder rollen eine Liste (auch Bild auf, Bild ab, Pos1 und Ende); Esc oder ein Klick in die Welt schaltet die Tastenkürzel wieder ein
keys-regions = F6 / Umschalt+F6
help-regions = zum nächsten Teil des Fensters springen: zur Steuerung (wird geöffnet, falls geschlossen; zuerst die Masse der gewählten Scheibe), zu den Reitern, zur oberen Leiste und zurück zur Welt; Tab geht dann darin weiter
keys-aim-keys = Pfeiltasten, angehalten, mit gewählter Scheibe
help-aim-keys = sie ausrichten: ihre Geschwindigkeit ±0,1 m/s pro Tastendruck (Umschalt: ±1 m/s)
keys-select-next = Q / Umschalt+Q
help-select-next = die nächste / die vorige Scheibe auswählen
keys-launch-centre = Enter
help-launch-centre = eine neue, ruhende Scheibe in der Mitte der Ansicht, gleich ausgewählt; in einer Lektion, die auf ihre Frage wartet: startet sie
keys-in-panels = Die Tasten bedienen jetzt die Bedienelemente: Esc oder ein Klick in die Welt schaltet die Tastenkürzel wieder ein.
keys-in-panels-short = Esc: Tastenkürzel wieder an
keys-tab-edge = Reiterhöhe: Pfeile eine Zeile, Pos1 am höchsten, Ende am niedrigsten, Enter: passende Höhe. Esc: Tastenkürzel wieder an.
keys-tab-edge-short = Pfeile, Pos1, Ende: Reiterhöhe
keys-after-field = Leertaste, N und J wirken auf die Simulation; die anderen Tastenkürzel warten: Esc oder ein Klick in die Welt schaltet sie wieder ein.

## Ton
keys-sound = F8
help-sound = Ton an / aus: ein Klicken bei jedem Aufprall, lauter bei einem härteren, höher zwischen Scheiben als an einer Wand (stumm, wenn angehalten oder schneller als ×2)
label-toggle-sound = Ton
sound-on = Ton an: ein Klicken bei jedem Aufprall (stumm, wenn angehalten oder schneller als ×2)
sound-off = Ton aus

## Für einen Screenreader (die Live-Region des Browsers, der Reiter In Worten)
said-pair = Scheibe { $a } traf Scheibe { $b }: Gesamtimpuls vorher { $before }, nachher { $after }
said-wall = Scheibe { $disc } traf die { $wall ->
    [left] linke
    [right] rechte
    [bottom] untere
   *[top] obere
 } Wand: Geschwindigkeit vorher { $before }, nachher { $after }
place-middle = in der Mitte
place-left = links
place-right = rechts
place-bottom = unten
place-top = oben
place-bottom-left = links unten
place-bottom-right = rechts unten
place-top-left = links oben
place-top-right = rechts oben
motion-rest = in Ruhe
motion-moving = bewegt sich mit { $speed } nach { $direction }
direction-right = rechts
direction-up-right = rechts oben
direction-up = oben
direction-up-left = links oben
direction-left = links
direction-down-left = links unten
direction-down = unten
direction-down-right = rechts unten
describe-box = { $discs ->
    [one] Eine Scheibe
   *[other] { $discs } Scheiben
 } in einem { $width } mal { $height } Meter großen { $edges ->
    [open] Raum ohne Wände.
    [periodic] Raum, dessen Seiten miteinander verbunden sind (eine Scheibe, die auf einer Seite hinausfliegt, kommt auf der gegenüberliegenden wieder herein).
   *[box] Kasten.
 }
describe-gravity = Die Schwerkraft zieht mit { $gravity } nach unten.
describe-no-gravity = Keine Schwerkraft.
describe-restitution = Stoßzahl zwischen Scheiben: { $restitution }.
describe-disc = Scheibe { $disc }: { $mass }; { $place }; { $motion }.
describe-more = { $more ->
    [one] Dazu kommt eine weitere Scheibe
   *[other] Dazu kommen { $more } weitere Scheiben
 }; ihre mittlere Geschwindigkeit beträgt { $speed }.
describe-totals = { $state ->
    [paused] Angehalten bei t = { $time }
   *[running] Läuft, t = { $time }
 }; Gesamtimpuls { $momentum }, kinetische Energie { $energy }.
tab-words = In Worten
# On the desktop; in the browser, where a screen reader reads the page.
words-line = Was geschieht, in Worten, das Neueste zuerst: höchstens ein Stoß alle { $gap } s (der Reiter { tab-collisions } listet alle).
words-line-web = Was geschieht, in Worten, das Neueste zuerst, wie ein Screenreader es vorliest: höchstens ein Stoß alle { $gap } s (der Reiter { tab-collisions } listet alle).
words-none = Noch nichts gesagt.
label-describe = Szene beschreiben
mirror-title = Impulse: Bedienelemente für Tastatur und Screenreader
mirror-canvas = Impulse, die Simulation: { $keys } zeigt die Tasten
mirror-said = Was geschieht
