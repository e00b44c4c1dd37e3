# Was der Sandkasten sagt: Meldungen in der Leiste, Hinweise unter Feldern, Fehler.

number-not-a-number = keine Zahl
discs-count = { $count ->
    [one] 1 Scheibe
   *[other] { $count } Scheiben
}

## Zählungen und Lektionen
count-line = Stöße: { $pairs } zwischen Scheiben
count-line-walls = Stöße: { $pairs } zwischen Scheiben · { $walls } mit Wänden
pi-result = { $count } Stöße: π ≈ { $pi }
pi-count = { $count ->
    [one] 1 Stoß
   *[other] { $count } Stöße
}

## Was ein Verfahren nicht versprechen kann
warning-verlet = verlet: Stöße verlieren Energie; die Stoßzahl e = { $restitution } wird nicht eingehalten
warning-seed = seed: schnelle Scheiben können durcheinander hindurchfliegen
warning-substeps = schnelle Scheiben können durcheinander hindurchfliegen: Die schnellste legt in einem kleinen Schritt { $radii }-mal ihren Radius zurück ({ $substeps ->
    [one] 1 Teilschritt
   *[other] { $substeps } Teilschritte
} pro Schritt; mehr davon, unter Mehr, verhindern es)
warning-stall = { $method }: zu viele Stöße auf einmal, die Zeit steht still. Rückgängig nimmt die Änderung zurück, die das auslöste; um so weiterzulaufen, das Verfahren impulse wählen (unter Mehr)

## Szenen und Dateien
file-cannot-create = { $folder } kann nicht angelegt werden: { $error }
file-cannot-write = { $file } kann nicht geschrieben werden: { $error }
scene-cannot-open = { $file } kann nicht geöffnet werden: { $error }
scene-opened = Geöffnet: { $name }
scene-opened-undo = Geöffnet: { $name }. { $undo } holt { $previous } zurück, so wie du es verlassen hast
scene-kept = { $error } (die aktuelle Szene bleibt)
scene-not-found = Keine Szenendatei { $name }, weder hier noch in { $folder } (die aktuelle Szene bleibt)
scene-reset = Szene zurückgesetzt
scene-reset-edits = Szene zurückgesetzt, wie sie geöffnet wurde, ohne deine Änderungen: { $undo } holt sie zurück
scene-back-to-setup = Zurück zu deinem Aufbau bei t = { $time } s; noch einmal { $reset }: die Szene, wie sie geöffnet wurde
scene-cannot-reset = Zurücksetzen nicht möglich: { $error }
scene-cleared = Geleert: auf freier Fläche ziehen, um Scheiben abzuschießen
scene-path-empty = Zuerst den Pfad einer Szenendatei eingeben
scene-downloaded = Heruntergeladen: { $file }
scene-saved = Gespeichert: { $file } in { $folder }
scene-saved-short = Gespeichert: { $file }
scene-saved-at = { $saved }, die Scheiben wie bei t = { $time } s
scene-renamed = Die Szene heißt jetzt { $name }
scene-name-empty = Ein Name braucht einen Buchstaben oder eine Ziffer
scene-not-saved = Nicht gespeichert: { $error }
screenshot-saved = Bildschirmfoto gespeichert: { $file }
screenshot-downloaded = Bildschirmfoto heruntergeladen: { $file }
screenshot-not-saved = Bildschirmfoto nicht gespeichert: { $error }
scene-shared = Die Adresse der Seite öffnet jetzt diese Szene: aus der Adressleiste kopieren und verschicken
scene-not-shared = Nicht geteilt: { $error }
undone = Rückgängig gemacht: { $what } (Strg+Umschalt+Z oder Strg+Y wiederholt es)
nothing-to-undo = Nichts rückgängig zu machen
redone = Wiederholt: { $what }
nothing-to-redo = Nichts zu wiederholen

## Was Rückgängig nennt
edit-open-scene = Szene öffnen
edit-reset = Zurücksetzen
edit-rename = Name der Szene
edit-clear = Leeren
edit-restitution = Stoßzahl
edit-wall-restitution = Stoßzahl der Wände
edit-roughness = Rauigkeit
edit-wall-roughness = Rauigkeit der Wände
edit-friction = Reibung
edit-gravity = Schwerkraft
edit-edges = Ränder
edit-method = Verfahren
edit-broad-phase = Grobphase
edit-substeps = Teilschritte
edit-disc = Scheibe bearbeiten
edit-delete = Löschen
edit-launch = Abschuss
edit-add-disc = neue Scheibe
edit-fling = Schleudern
edit-aim = Geschwindigkeit festlegen
no-room = Hier ist kein Platz für eine neue Scheibe

## Mit einer Taste geänderte Einstellungen
law-restitution = Stoßzahl e
law-wall-restitution = Stoßzahl der Wände
law-roughness = Rauigkeit β
law-wall-roughness = Rauigkeit der Wände β
time-scale = Zeitfaktor ×{ $scale }
gravity-now = Schwerkraft { $gravity }
method-now = Verfahren: { $method }
broad-phase-now = Grobphase: { $broad }
substeps-now = Teilschritte: { $substeps }
new-disc-radius = Neue Scheiben: Radius { $radius }
new-disc-mass = Neue Scheiben: Masse { $mass }
palette-safe = Scheiben in Farben für Farbenblinde (Okabe-Ito, nach Scheibennummer)
palette-scene = Scheiben in den Farben der Szene
text-size = Textgröße ×{ $scale }
com-view-off = Schwerpunktsystem aus: Geschwindigkeiten vom Kasten aus gesehen
com-view-on = Schwerpunktsystem: Die Ansicht bewegt sich mit dem Schwerpunkt, mit { $velocity }; nochmals Z zum Verlassen

## Zeit: nächster Stoß, Zurückspulen, Export
separated = Das Verfahren exact braucht getrennte Scheiben: Es hat { $pairs ->
    [one] 1 überlappendes Scheibenpaar
   *[other] { $pairs } überlappende Scheibenpaare
} getrennt
separated-raised = Das Verfahren exact braucht getrennte Scheiben: Es hat { $pairs ->
    [one] 1 überlappendes Scheibenpaar
   *[other] { $pairs } überlappende Scheibenpaare
} getrennt, was die Energie um { $energy } erhöht hat
separated-lowered = Das Verfahren exact braucht getrennte Scheiben: Es hat { $pairs ->
    [one] 1 überlappendes Scheibenpaar
   *[other] { $pairs } überlappende Scheibenpaare
} getrennt, was die Energie um { $energy } verringert hat
next-collision-pair = Scheiben { $a } und { $b }, t = { $time }: { $momentum_kept ->
    [yes] Gesamtimpuls unverändert
   *[no] Gesamtimpuls um { $momentum } geändert
}, { $energy_change ->
    [same] kinetische Energie unverändert
    [less] kinetische Energie um { $energy } kleiner
   *[more] kinetische Energie um { $energy } größer
}
next-collision-wall = Scheibe { $disc } traf die { $wall ->
    [left] linke
    [right] rechte
    [bottom] untere
   *[top] obere
 } Wand, t = { $time }: Die Wand gab ihr einen Kraftstoß von { $impulse }; { $energy_change ->
    [same] ihre kinetische Energie unverändert
    [less] ihre kinetische Energie um { $energy } kleiner
   *[more] ihre kinetische Energie um { $energy } größer
}
next-collision-verlet = Scheiben sind bei t = { $time } zusammengestoßen; verlet schiebt Positionen auseinander und hat daher kein Vorher und Nachher eines einzelnen Stoßes zu zeigen: Der Reiter Stöße hat dafür keine Zeile
stepped = { $steps ->
    [one] Ein Schritt
   *[other] { $steps } Schritte
} von { $dt }: t = { $time }
next-collision-none = Kein Stoß innerhalb von { $limit }
next-collision-at-once = { $impacts } Stöße im selben Augenblick, alle im Reiter Stöße aufgeführt. { $first }
rewound-to = Zurückgespult auf t = { $time } s (aufgezeichnet: { $oldest } bis { $newest } s); die Leertaste setzt von hier aus fort
rewound-newest = Beim neuesten aufgezeichneten Augenblick, t = { $time } s; die Leertaste läuft von hier aus weiter
nothing-recorded = Noch nichts aufgezeichnet
exported-downloaded = Bilanz, Scheiben, Stöße und Wandstöße als CSV-Dateien heruntergeladen
exported = Bilanz, Scheiben, Stöße und Wandstöße nach { $folder }/ exportiert
not-exported = Nicht nach { $folder }/ exportiert: { $error }
wall-name = { $wall ->
    [left] linke Wand
    [right] rechte Wand
    [bottom] untere Wand
   *[top] obere Wand
}

## Eine Scheibe bearbeiten
edit-type-a-number = { $name }: eine Zahl eingeben
edit-not-a-number = { $name }: „{ $text }“ ist keine Zahl
edit-ambiguous-number = { $name }: „{ $text }“ kann { $decimal } oder { $grouped } heißen; gib die gemeinte Zahl ein
edit-not-finite = { $name } muss eine endliche Zahl sein
edit-speed-negative = Das Tempo kann nicht negativ sein: gib stattdessen die Gegenrichtung ein
edit-not-positive = { $name } muss größer als 0 sein
edit-radius-too-large = Der Radius darf hier höchstens { $radius } m betragen
edit-out-of-range = { $name } muss zwischen { $lo } und { $hi } liegen
edit-too-fast = Die Geschwindigkeit darf höchstens 10⁸ m/s betragen
slider-out-of-range = { $typed } liegt außerhalb von { $low } bis { $high }: eingestellt auf { $value }
slider-sign-dropped = { $typed } wird als { $value } gelesen: Die Richtung steht schon im Namen
edit-across-the-line = Hier bewegen sich die Scheiben auf einer Geraden: { $name } muss 0 sein
edit-nothing-changed = Nichts geändert: zuerst einen neuen Wert eingeben
edit-pending = Eingetippt, noch nicht übernommen: Enter oder Übernehmen
edit-applied = Für Scheibe { $disc } übernommen
edit-applied-table = Scheibe { $disc }: { $values }
edit-refused-table = Scheibe { $disc }: { $error }; nichts geändert
edit-mass-overlaps = bei { $mass } kg hätte die Scheibe { $size } m Radius (Größe folgt der Masse) und würde Scheibe { $disc } überlappen
edit-mass-crosses-wall = bei { $mass } kg hätte die Scheibe { $size } m Radius (Größe folgt der Masse) und würde über eine Wand hinausragen
edit-position-off-the-line = Hier bewegen sich die Scheiben auf einer Geraden: { $name } bleibt { $value } m
edit-position-crosses-wall = bei { $at } würde die Scheibe über eine Wand hinausragen
edit-position-overlaps = bei { $at } würde die Scheibe mit Scheibe { $disc } überlappen
edit-radius-crosses-wall = mit { $radius } m Radius würde die Scheibe über eine Wand hinausragen
edit-radius-overlaps = mit { $radius } m Radius würde die Scheibe mit Scheibe { $disc } überlappen

## Wiederherstellung
recovery-unreadable-moved = Eine unlesbare Wiederherstellungsdatei wurde nach { $file } verschoben: { $error }
recovery-unreadable-kept = Eine unlesbare Wiederherstellungsdatei konnte nicht verschoben werden: { $error }
autosave-failed = Automatisches Speichern in { $place } fehlgeschlagen: { $error }
browser-storage = den Speicher des Browsers
origin-recovered = wiederhergestellt aus { $file }
origin-kept = dein letzter Sandkasten, von diesem Browser aufbewahrt
recovery-kept-in = Frühere Sitzung aufbewahrt in { $file }
recovery-restored = { $name } wiederhergestellt, angehalten, wo es aufhörte: Leertaste startet
recovery-not-set-aside = Die frühere Sitzung konnte nicht beiseitegelegt werden: { $error }
kept-not-set-aside = Dein letzter Sandkasten konnte nicht beiseitegelegt werden: { $error }
recovery-question-browser = Dieser Browser hat deinen letzten Sandkasten aufbewahrt: { $name } ({ $discs ->
    [one] 1 Scheibe
   *[other] { $discs } Scheiben
}). Wiederherstellen oder beiseitelegen?
recovery-question = Die letzte Sitzung endete mit ungespeicherten Änderungen. Deine Szene { $name } ({ $discs ->
    [one] 1 Scheibe
   *[other] { $discs } Scheiben
}) wiederherstellen oder beiseitelegen?
sandbox-cannot-open = Der Sandkasten kann nicht geöffnet werden: { $error }
link-too-many-discs = { $discs } Scheiben sind zu viele für einen Link (höchstens { $most }): die Szene stattdessen als Datei speichern
link-damaged = die Szene im Link ist beschädigt ({ $error })
settings-unreadable = Die Einstellungen in { $file } konnten nicht gelesen werden ({ $error }): Es gelten die Standardwerte
settings-not-saved = Die Einstellungen wurden nicht in { $place } gespeichert: { $error }
aimed = Scheibe { $disc }: Geschwindigkeit auf { $velocity } gesetzt
aim-across-the-line = Hier bewegen sich die Scheiben auf einer Geraden: { $keys } zielen entlang der Geraden
key-left-right = Links und Rechts
key-up-down = Hoch und Runter
dropped-file = abgelegte Datei
dropped-not-text = { $name }: keine Textdatei
dropped-unreadable = { $name }: { $error }
dropped-empty = eine abgelegte Datei ohne Inhalt
link-cannot-open = Die Szene dieses Links kann nicht geöffnet werden: { $error }
origin-default = eingebaute Standardszene
origin-shared-link = der geteilte Link
