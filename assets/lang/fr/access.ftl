# Accès au clavier, au son et aux lecteurs d'écran : ce qu'en dit la fenêtre.

select-no-discs = Aucun disque à sélectionner : Entrée en place un au centre.
selected-disc-said = Disque { $disc } sur { $discs } sélectionné : { $mass }; vitesse { $velocity }
launched-at-centre = Disque { $disc } au repos au centre : simulation en pause, les touches fléchées règlent sa vitesse
launched-near-centre = Disque { $disc } au repos à côté du disque { $beside } (le centre était pris) : simulation en pause, les touches fléchées règlent sa vitesse

## Le parcours au clavier (lignes de l'aide)
keys-focus = Tab / Maj+Tab
help-focus = parcourir les commandes dans l'ordre de lecture ; Espace ou Entrée en actionne une, les touches fléchées déplacent un curseur de réglage, choisissent dans une liste déroulante ou font défiler une liste (Page préc., Page suiv., Début et Fin aussi) ; Échap ou un clic dans la simulation réactive les raccourcis clavier
keys-regions = F6 / Maj+F6
help-regions = passer à la partie suivante de la fenêtre : les réglages (ouverts s'ils sont fermés ; d'abord la masse du disque sélectionné), les onglets, la barre du haut, puis retour à la simulation ; Tab avance ensuite à l'intérieur
keys-aim-keys = Touches fléchées, en pause, avec un disque sélectionné
help-aim-keys = régler sa vitesse : ±0,1 m/s par appui (Maj : ±1 m/s)
keys-select-next = Q / Maj+Q
help-select-next = sélectionner le disque suivant / précédent
keys-launch-centre = Entrée
help-launch-centre = un nouveau disque au repos au centre de la vue, sélectionné ; dans une leçon qui attend sur sa question, la lance
keys-in-panels = Les touches agissent maintenant sur les commandes : Échap ou un clic dans la simulation réactive les raccourcis clavier.
keys-in-panels-short = Échap : réactiver les raccourcis
keys-tab-edge = Hauteur : flèches une ligne, Début le plus haut, Fin le plus bas, Entrée la sienne. Échap : réactiver les raccourcis.
keys-tab-edge-short = Flèches, Début, Fin : hauteur
keys-after-field = Espace, N et J agissent sur la simulation ; les autres raccourcis attendent : Échap ou un clic dans la simulation les réactive.

## Le son
keys-sound = F8
help-sound = son activé / désactivé : un clic à chaque choc, plus fort pour un choc plus violent, plus aigu entre disques que contre un mur (muet en pause ou au-delà de ×2)
label-toggle-sound = Son
sound-on = Son activé : un clic à chaque choc (muet en pause ou au-delà de ×2)
sound-off = Son désactivé

## Ce qui est dit à un lecteur d'écran (la zone dynamique du navigateur, l'onglet Récit)
said-pair = Le disque { $a } a heurté le disque { $b } : quantité de mouvement totale avant { $before }, après { $after }
said-wall = Le disque { $disc } a heurté le mur { $wall ->
    [left] de gauche
    [right] de droite
    [bottom] du bas
   *[top] du haut
 } : vitesse avant { $before }, après { $after }
place-middle = au milieu
place-left = à gauche
place-right = à droite
place-bottom = en bas
place-top = en haut
place-bottom-left = en bas à gauche
place-bottom-right = en bas à droite
place-top-left = en haut à gauche
place-top-right = en haut à droite
motion-rest = au repos
motion-moving = en mouvement { $direction } à { $speed }
direction-right = vers la droite
direction-up-right = vers le haut et vers la droite
direction-up = vers le haut
direction-up-left = vers le haut et vers la gauche
direction-left = vers la gauche
direction-down-left = vers le bas et vers la gauche
direction-down = vers le bas
direction-down-right = vers le bas et vers la droite
describe-box = { $discs ->
    [one] { $discs } disque
   *[other] { $discs } disques
 } { $edges ->
    [open] dans un espace sans murs de { $width } m sur { $height } m.
    [periodic] dans un espace de { $width } m sur { $height } m dont les côtés se rejoignent (un disque qui sort d'un côté revient par l'autre).
   *[box] dans une boîte de { $width } m sur { $height } m.
 }
describe-gravity = La pesanteur tire vers le bas, avec une intensité de { $gravity }.
describe-no-gravity = Pas de pesanteur.
describe-restitution = Coefficient de restitution entre disques : { $restitution }.
describe-disc = Disque { $disc }: { $mass }; { $place }; { $motion }.
describe-more = { $more ->
    [one] Et { $more } autre disque
   *[other] Et { $more } autres disques
 } ; leur vitesse moyenne est de { $speed }.
describe-totals = { $state ->
    [paused] En pause
   *[running] En cours
 } à t = { $time } ; quantité de mouvement totale { $momentum }, énergie cinétique { $energy }.
tab-words = Récit
# On the desktop; in the browser, where a screen reader reads the page.
words-line = Ce qui se passe, raconté avec des mots, le plus récent en premier : un choc toutes les { $gap } s au plus (l'onglet { tab-collisions } les liste tous).
words-line-web = Ce qui se passe, raconté avec des mots, le plus récent en premier, tel qu'un lecteur d'écran le lit : un choc toutes les { $gap } s au plus (l'onglet { tab-collisions } les liste tous).
words-none = Rien n'a encore été dit.
label-describe = Décrire la scène
mirror-title = Impulse : commandes pour le clavier et les lecteurs d'écran
mirror-canvas = Impulse, la simulation : { $keys } affiche les touches
mirror-said = Ce qui se passe
