# Ce que dit le bac à sable : messages du bandeau, notes sous les champs, erreurs.

number-not-a-number = ce n'est pas un nombre
discs-count = { $count ->
    [one] { $count } disque
   *[other] { $count } disques
}

## Comptages et leçons
count-line = collisions : { $pairs } entre disques
count-line-walls = collisions : { $pairs } entre disques · { $walls } avec les murs
pi-result = { $count } collisions : π ≈ { $pi }
pi-count = { $count ->
    [one] 1 collision
   *[other] { $count } collisions
}

## Ce qu'une méthode ne peut pas promettre
warning-verlet = verlet : les collisions perdent de l'énergie ; le coefficient de restitution e = { $restitution } n'est pas respecté
warning-seed = seed : des disques rapides peuvent se traverser
warning-substeps = des disques rapides peuvent se traverser : le plus rapide parcourt { $radii }× son rayon en un petit pas ({ $substeps ->
    [one] { $substeps } sous-pas
   *[other] { $substeps } sous-pas
} par pas ; davantage de sous-pas, sous Plus, l'empêchent)
warning-stall = { $method } : trop de collisions à la fois, le temps s'est arrêté. Annuler retire le changement qui l'a causé ; pour continuer ainsi, choisissez la méthode impulse (sous Plus)

## Scènes et fichiers
file-cannot-create = impossible de créer { $folder } : { $error }
file-cannot-write = impossible d'écrire { $file } : { $error }
scene-cannot-open = Impossible d'ouvrir { $file } : { $error }
scene-opened = Ouvert : { $name }
scene-opened-undo = Ouvert : { $name }. { $undo } ramène { $previous } tel que vous l’avez laissé
scene-kept = { $error } (la scène actuelle est conservée)
scene-not-found = Aucun fichier de scène { $name }, ni ici ni dans { $folder } (la scène actuelle est conservée)
scene-reset = Scène réinitialisée
scene-reset-edits = Scène réinitialisée telle qu’elle a été ouverte, sans vos modifications : { $undo } les ramène
scene-back-to-setup = Retour à votre mise en place à t = { $time } s ; { $reset } à nouveau : la scène telle qu'elle a été ouverte
scene-cannot-reset = Impossible de réinitialiser : { $error }
scene-cleared = Disques effacés : glissez dans le vide pour en lancer
scene-path-empty = Tapez d'abord le chemin d'un fichier de scène
scene-downloaded = Téléchargé : { $file }
scene-saved = Enregistré : { $file } dans { $folder }
scene-saved-short = Enregistré : { $file }
scene-saved-at = { $saved }, les disques tels qu'à t = { $time } s
scene-renamed = La scène s'appelle maintenant { $name }
scene-name-empty = Un nom doit contenir une lettre ou un chiffre
scene-not-saved = Non enregistré : { $error }
screenshot-saved = Capture d'écran enregistrée : { $file }
screenshot-downloaded = Capture d'écran téléchargée : { $file }
screenshot-not-saved = Capture d'écran non enregistrée : { $error }
scene-shared = L'adresse de la page ouvre maintenant cette scène : copiez-la depuis la barre d'adresse et envoyez-la
scene-not-shared = Non partagé : { $error }
undone = Annulé : { $what } (Ctrl+Maj+Z ou Ctrl+Y pour rétablir)
nothing-to-undo = Rien à annuler
redone = Rétabli : { $what }
nothing-to-redo = Rien à rétablir

## Ce que nomme l'annulation
edit-open-scene = ouverture d'une scène
edit-reset = réinitialisation
edit-rename = nom de la scène
edit-clear = effacement des disques
edit-restitution = restitution
edit-wall-restitution = restitution aux murs
edit-roughness = rugosité
edit-wall-roughness = rugosité des murs
edit-friction = frottement
edit-gravity = pesanteur
edit-edges = bords
edit-method = méthode
edit-broad-phase = phase large
edit-substeps = sous-pas
edit-disc = modification d'un disque
edit-delete = suppression
edit-launch = lancement d'un disque
edit-add-disc = ajout d'un disque
edit-fling = disque attrapé et lancé
edit-aim = réglage d'une vitesse
no-room = Pas de place ici pour un nouveau disque

## Réglages modifiés par une touche
law-restitution = Restitution e
law-wall-restitution = Restitution aux murs
law-roughness = Rugosité β
law-wall-roughness = Rugosité des murs β
time-scale = Échelle de temps ×{ $scale }
gravity-now = Pesanteur { $gravity }
method-now = Méthode : { $method }
broad-phase-now = Phase large : { $broad }
substeps-now = Sous-pas : { $substeps }
new-disc-radius = Nouveaux disques : rayon { $radius }
new-disc-mass = Nouveaux disques : masse { $mass }
palette-safe = Disques en couleurs adaptées aux daltoniens (Okabe-Ito, selon le numéro du disque)
palette-scene = Disques aux couleurs de la scène
text-size = Taille du texte ×{ $scale }
com-view-off = Vue du centre de masse désactivée : vitesses vues depuis la boîte
com-view-on = Vue du centre de masse : la vue suit le centre de masse, qui se déplace à { $velocity } ; Z à nouveau pour en sortir

## Le temps : collision suivante, retour en arrière, export
separated = La méthode exact exige des disques séparés : { $pairs ->
    [one] { $pairs } paire de disques qui se chevauchaient a été séparée
   *[other] { $pairs } paires de disques qui se chevauchaient ont été séparées
}
separated-raised = La méthode exact exige des disques séparés : { $pairs ->
    [one] { $pairs } paire de disques qui se chevauchaient a été séparée
   *[other] { $pairs } paires de disques qui se chevauchaient ont été séparées
}, ce qui a augmenté l'énergie de { $energy }
separated-lowered = La méthode exact exige des disques séparés : { $pairs ->
    [one] { $pairs } paire de disques qui se chevauchaient a été séparée
   *[other] { $pairs } paires de disques qui se chevauchaient ont été séparées
}, ce qui a diminué l'énergie de { $energy }
next-collision-pair = Disques { $a } et { $b }, t = { $time } : { $momentum_kept ->
    [yes] quantité de mouvement totale inchangée
   *[no] quantité de mouvement totale modifiée de { $momentum }
}, { $energy_change ->
    [same] énergie cinétique inchangée
    [less] énergie cinétique en baisse de { $energy }
   *[more] énergie cinétique en hausse de { $energy }
}
next-collision-wall = Le disque { $disc } a heurté le mur { $wall ->
    [left] de gauche
    [right] de droite
    [bottom] du bas
   *[top] du haut
}, t = { $time } : la poussée du mur a changé sa quantité de mouvement de { $impulse } ; { $energy_change ->
    [same] son énergie cinétique est inchangée
    [less] son énergie cinétique est en baisse de { $energy }
   *[more] son énergie cinétique est en hausse de { $energy }
}
next-collision-verlet = Des disques se sont heurtés à t = { $time } ; verlet écarte les positions, il n'y a donc pas d'avant et d'après d'une collision à montrer : le registre n'a pas de ligne pour elle
stepped = { $steps ->
    [one] Un pas
   *[other] { $steps } pas
} de { $dt } : t = { $time }
next-collision-none = Aucune collision en { $limit }
next-collision-at-once = { $impacts } chocs au même instant, tous indiqués dans l’onglet Collisions. { $first }
rewound-to = Retour à t = { $time } s (enregistré : de { $oldest } à { $newest } s) ; Espace reprend à partir d'ici
rewound-newest = Au dernier instant enregistré, t = { $time } s ; Espace reprend à partir d'ici
nothing-recorded = Rien d'enregistré pour l'instant
exported-downloaded = Totaux, disques, collisions et chocs contre les murs téléchargés en fichiers CSV
exported = Totaux, disques, collisions et chocs contre les murs exportés dans { $folder }/
not-exported = Non exporté dans { $folder } : { $error }
wall-name = { $wall ->
    [left] mur de gauche
    [right] mur de droite
    [bottom] mur du bas
   *[top] mur du haut
}

## Modifier un disque
edit-type-a-number = { $name } : tapez un nombre
edit-not-a-number = { $name } : « { $text } » n'est pas un nombre
edit-ambiguous-number = { $name } : « { $text } » peut se lire { $decimal } ou { $grouped } ; tapez celui que vous voulez dire
edit-not-finite = { $name } : il faut un nombre fini
edit-speed-negative = La vitesse ne peut pas être négative : tapez plutôt la direction opposée
edit-not-positive = { $name } : il faut une valeur supérieure à 0
edit-radius-too-large = le rayon ne peut pas dépasser { $radius } m ici
edit-out-of-range = { $name } : il faut une valeur entre { $lo } et { $hi }
edit-too-fast = la vitesse ne peut pas dépasser 10⁸ m/s
slider-out-of-range = { $typed } est hors de l'intervalle de { $low } à { $high } : la valeur retenue est { $value }
slider-sign-dropped = { $typed } est lu comme { $value } : le nom indique déjà le sens
edit-across-the-line = ici les disques se déplacent sur une droite : { $name } doit valoir 0
edit-nothing-changed = Rien n'a changé : tapez d'abord une nouvelle valeur
edit-pending = Saisi, pas encore appliqué : Entrée ou Appliquer
edit-applied = Appliqué au disque { $disc }
edit-applied-table = Disque { $disc } : { $values }
edit-refused-table = Disque { $disc } : { $error } ; rien n'a changé
edit-mass-overlaps = avec { $mass } kg, le disque aurait un rayon de { $size } m (taille selon la masse) et chevaucherait le disque { $disc }
edit-mass-crosses-wall = avec { $mass } kg, le disque aurait un rayon de { $size } m (taille selon la masse) et traverserait un mur
edit-position-off-the-line = ici les disques se déplacent sur une droite : { $name } reste { $value } m
edit-position-crosses-wall = en { $at }, le disque traverserait un mur
edit-position-overlaps = en { $at }, le disque chevaucherait le disque { $disc }
edit-radius-crosses-wall = avec un rayon de { $radius } m, le disque traverserait un mur
edit-radius-overlaps = avec un rayon de { $radius } m, le disque chevaucherait le disque { $disc }

## Récupération
recovery-unreadable-moved = Un fichier de récupération illisible a été déplacé vers { $file } : { $error }
recovery-unreadable-kept = Un fichier de récupération illisible n'a pas pu être déplacé : { $error }
autosave-failed = L'enregistrement automatique dans { $place } a échoué : { $error }
browser-storage = le stockage du navigateur
origin-recovered = récupérée depuis { $file }
origin-kept = votre dernier bac à sable, gardé par ce navigateur
recovery-kept-in = Session précédente gardée dans { $file }
recovery-restored = { $name } restauré, en pause là où il s'était arrêté : Espace le relance
recovery-not-set-aside = Impossible de mettre de côté la session précédente : { $error }
kept-not-set-aside = Impossible de mettre de côté votre dernier bac à sable : { $error }
recovery-question-browser = Ce navigateur a gardé votre dernier bac à sable, « { $name } » ({ $discs ->
    [one] { $discs } disque
   *[other] { $discs } disques
}). Le restaurer, ou le mettre de côté ?
recovery-question = La dernière session s'est terminée avec des modifications non enregistrées. Restaurer sa scène « { $name } » ({ $discs ->
    [one] { $discs } disque
   *[other] { $discs } disques
}), ou la mettre de côté ?
sandbox-cannot-open = Impossible d'ouvrir le bac à sable : { $error }
link-too-many-discs = { $discs } disques, c'est trop pour un lien (au plus { $most }) : enregistrez plutôt la scène dans un fichier
link-damaged = la scène du lien est endommagée ({ $error })
settings-unreadable = Les réglages de { $file } n'ont pas pu être lus ({ $error }) : les valeurs par défaut s'appliquent
settings-not-saved = Les réglages n'ont pas été enregistrés dans { $place } : { $error }
aimed = Disque { $disc } : vitesse réglée à { $velocity }
aim-across-the-line = Ici les disques se déplacent sur une droite : { $keys } visent le long de la droite
key-left-right = Gauche et Droite
key-up-down = Haut et Bas
dropped-file = fichier déposé
dropped-not-text = { $name } : ce n'est pas un fichier texte
dropped-unreadable = { $name } : { $error }
dropped-empty = un fichier déposé sans contenu
link-cannot-open = La scène de ce lien ne peut pas s'ouvrir : { $error }
origin-default = scène par défaut intégrée
origin-shared-link = le lien partagé
