# O que a caixa diz: mensagens na faixa, notas embaixo dos campos, erros.

number-not-a-number = não é um número
discs-count = { $count ->
    [one] { $count } disco
   *[other] { $count } discos
}

## Contagens e lições
count-line = colisões: { $pairs } entre discos
count-line-walls = colisões: { $pairs } entre discos · { $walls } com paredes
pi-result = { $count } colisões: π ≈ { $pi }
pi-count = { $count ->
    [one] 1 colisão
   *[other] { $count } colisões
}

## O que um método não pode prometer
warning-verlet = verlet: as colisões perdem energia; o coeficiente de restituição e = { $restitution } não é respeitado
warning-seed = seed: discos rápidos podem atravessar uns aos outros
warning-substeps = discos rápidos podem atravessar uns aos outros: o mais rápido anda { $radii }× o seu raio num passo pequeno ({ $substeps ->
    [one] 1 subpasso
   *[other] { $substeps } subpassos
} por passo; mais subpassos, em Mais, evitam isso)
warning-stall = { $method }: colisões demais ao mesmo tempo, e o tempo parou. Desfazer tira a mudança que causou isso; para continuar assim, escolha o método impulse (em Mais)

## Cenas e arquivos
file-cannot-create = não foi possível criar { $folder }: { $error }
file-cannot-write = não foi possível gravar { $file }: { $error }
scene-cannot-open = Não foi possível abrir { $file }: { $error }
scene-opened = Cena aberta: { $name }
scene-opened-undo = Cena aberta: { $name }. { $undo } traz de volta { $previous } como você deixou
scene-kept = { $error } (a cena atual foi mantida)
scene-not-found = Não há arquivo de cena { $name }, nem aqui nem em { $folder } (a cena atual foi mantida)
scene-reset = Cena reiniciada
scene-reset-edits = Cena reiniciada como foi aberta, sem as suas alterações: { $undo } as traz de volta
scene-back-to-setup = De volta à sua montagem em t = { $time } s; { $reset } de novo: a cena como foi aberta
scene-cannot-reset = Não foi possível reiniciar: { $error }
scene-cleared = Cena limpa: arraste num espaço vazio para lançar discos
scene-path-empty = Digite primeiro o caminho de um arquivo de cena
scene-downloaded = Baixado: { $file }
scene-saved = Cena salva: { $file } em { $folder }
scene-saved-short = Cena salva: { $file }
scene-saved-at = { $saved }, com os discos como estavam em t = { $time } s
scene-renamed = A cena agora se chama { $name }
scene-name-empty = Um nome precisa de uma letra ou um dígito
scene-not-saved = Não foi salvo: { $error }
screenshot-saved = Captura de tela salva: { $file }
screenshot-downloaded = Captura de tela baixada: { $file }
screenshot-not-saved = Captura de tela não foi salva: { $error }
scene-shared = O endereço da página agora abre esta cena: copie-o da barra de endereço e envie
scene-not-shared = Não foi compartilhado: { $error }
undone = Desfeito: { $what } (Ctrl+Shift+Z ou Ctrl+Y refaz)
nothing-to-undo = Nada para desfazer
redone = Refeito: { $what }
nothing-to-redo = Nada para refazer

## Como o desfazer chama as alterações
edit-open-scene = abrir uma cena
edit-reset = reiniciar
edit-rename = nome da cena
edit-clear = limpar
edit-restitution = restituição
edit-wall-restitution = restituição nas paredes
edit-roughness = rugosidade
edit-wall-roughness = rugosidade nas paredes
edit-friction = atrito
edit-gravity = gravidade
edit-edges = bordas
edit-method = método
edit-broad-phase = fase ampla
edit-substeps = subpassos
edit-disc = editar um disco
edit-delete = excluir
edit-launch = lançar
edit-add-disc = disco novo
edit-fling = arremessar
edit-aim = definir uma velocidade
no-room = Sem espaço para um disco novo aqui

## Ajustes mudados por uma tecla
law-restitution = Restituição e
law-wall-restitution = Restituição nas paredes
law-roughness = Rugosidade β
law-wall-roughness = Rugosidade nas paredes β
time-scale = Escala de tempo ×{ $scale }
gravity-now = Gravidade { $gravity }
method-now = Método: { $method }
broad-phase-now = Fase ampla: { $broad }
substeps-now = Subpassos: { $substeps }
new-disc-radius = Discos novos: raio { $radius }
new-disc-mass = Discos novos: massa { $mass }
palette-safe = Discos em cores para daltônicos (Okabe-Ito, pelo número do disco)
palette-scene = Discos nas cores da cena
text-size = Tamanho do texto ×{ $scale }
com-view-off = Vista do centro de massa desligada: velocidades vistas a partir da caixa
com-view-on = Vista do centro de massa: acompanhando o centro de massa a { $velocity }; Z de novo para sair

## Tempo: próxima colisão, voltar, exportar
separated = O método exact precisa dos discos separados: separou { $pairs ->
    [one] { $pairs } par de discos sobrepostos
   *[other] { $pairs } pares de discos sobrepostos
}
separated-raised = O método exact precisa dos discos separados: separou { $pairs ->
    [one] { $pairs } par de discos sobrepostos
   *[other] { $pairs } pares de discos sobrepostos
}, o que aumentou a energia em { $energy }
separated-lowered = O método exact precisa dos discos separados: separou { $pairs ->
    [one] { $pairs } par de discos sobrepostos
   *[other] { $pairs } pares de discos sobrepostos
}, o que diminuiu a energia em { $energy }
next-collision-pair = Discos { $a } e { $b }, t = { $time }: { $momentum_kept ->
    [yes] quantidade de movimento total inalterada
   *[no] a quantidade de movimento total variou { $momentum }
}, { $energy_change ->
    [same] energia cinética inalterada
    [less] energia cinética { $energy } menor
   *[more] energia cinética { $energy } maior
}
next-collision-wall = O disco { $disc } bateu na parede { $wall ->
    [left] esquerda
    [right] direita
    [bottom] inferior
   *[top] superior
    }, t = { $time }: a parede aplicou nele um impulso de { $impulse }; { $energy_change ->
    [same] a energia cinética dele ficou inalterada
    [less] a energia cinética dele ficou { $energy } menor
   *[more] a energia cinética dele ficou { $energy } maior
}
next-collision-verlet = Discos colidiram em t = { $time }; o verlet afasta as posições, então não tem um antes e depois de uma colisão para mostrar: o registro não tem linha para ela
stepped = { $steps ->
    [one] Um passo
   *[other] { $steps } passos
} de { $dt }: t = { $time }
next-collision-none = Nenhuma colisão em { $limit }
next-collision-at-once = { $impacts } impactos no mesmo instante, todos listados na aba Colisões. { $first }
rewound-to = Voltou para t = { $time } s (gravado: { $oldest } a { $newest } s); Espaço continua daqui
rewound-newest = No momento gravado mais recente, t = { $time } s; Espaço continua daqui
nothing-recorded = Nada gravado ainda
exported-downloaded = Totais, discos, colisões e impactos nas paredes baixados como arquivos CSV
exported = Totais, discos, colisões e impactos nas paredes exportados para { $folder }/
not-exported = Não foi exportado para { $folder }: { $error }
wall-name = { $wall ->
    [left] parede esquerda
    [right] parede direita
    [bottom] parede inferior
   *[top] parede superior
}

## Editar um disco
edit-type-a-number = { $name }: digite um número
edit-not-a-number = { $name }: “{ $text }” não é um número
edit-ambiguous-number = { $name }: “{ $text }” pode ser { $decimal } ou { $grouped }; digite o que você quer dizer
edit-not-finite = { $name } precisa ser um número finito
edit-speed-negative = O módulo da velocidade não pode ser negativo: digite a direção oposta
edit-not-positive = { $name } precisa ser maior que 0
edit-radius-too-large = o raio pode ser no máximo { $radius } m aqui
edit-out-of-range = { $name } precisa estar entre { $lo } e { $hi }
edit-too-fast = a velocidade pode ser no máximo 10⁸ m/s
slider-out-of-range = { $typed } está fora do intervalo de { $low } a { $high }: ficou em { $value }
slider-sign-dropped = { $typed } é lido como { $value }: o nome já indica a direção
edit-across-the-line = aqui os discos se movem sobre uma reta: { $name } precisa ser 0
edit-nothing-changed = Nada mudou: digite primeiro um valor novo
edit-pending = Digitado, ainda não aplicado: Enter ou Aplicar
edit-applied = Aplicado ao disco { $disc }
edit-applied-table = Disco { $disc }: { $values }
edit-refused-table = Disco { $disc }: { $error }; nada mudou
edit-mass-overlaps = com { $mass } kg o disco teria { $size } m de raio (tamanho segue a massa) e se sobreporia ao disco { $disc }
edit-mass-crosses-wall = com { $mass } kg o disco teria { $size } m de raio (tamanho segue a massa) e atravessaria uma parede
edit-position-off-the-line = aqui os discos se movem sobre uma reta: { $name } fica em { $value } m
edit-position-crosses-wall = em { $at } o disco atravessaria uma parede
edit-position-overlaps = em { $at } o disco se sobreporia ao disco { $disc }
edit-radius-crosses-wall = com { $radius } m de raio o disco atravessaria uma parede
edit-radius-overlaps = com { $radius } m de raio o disco se sobreporia ao disco { $disc }

## Recuperação
recovery-unreadable-moved = Um arquivo de recuperação ilegível foi movido para { $file }: { $error }
recovery-unreadable-kept = Um arquivo de recuperação ilegível não pôde ser movido: { $error }
autosave-failed = O salvamento automático em { $place } falhou: { $error }
browser-storage = o armazenamento do navegador
origin-recovered = recuperada de { $file }
origin-kept = a sua última caixa livre, guardada por este navegador
recovery-kept-in = Sessão anterior guardada em { $file }
recovery-restored = { $name } restaurado, pausado onde parou: Espaço o põe para rodar
recovery-not-set-aside = Não foi possível deixar de lado a sessão anterior: { $error }
kept-not-set-aside = Não foi possível guardar à parte a sua última caixa livre: { $error }
recovery-question-browser = Este navegador guardou a sua última caixa livre, { $name } ({ $discs ->
    [one] { $discs } disco
   *[other] { $discs } discos
}). Restaurar ou deixar de lado?
recovery-question = A última sessão terminou com alterações não salvas. Restaurar a cena dela, { $name } ({ $discs ->
    [one] { $discs } disco
   *[other] { $discs } discos
}), ou deixar de lado?
sandbox-cannot-open = Não foi possível abrir a caixa livre: { $error }
link-too-many-discs = { $discs } discos são demais para um link (no máximo { $most }): salve a cena como arquivo
link-damaged = a cena do link está danificada ({ $error })
settings-unreadable = Não foi possível ler as configurações em { $file } ({ $error }): valem as configurações padrão
settings-not-saved = As configurações não foram salvas em { $place }: { $error }
aimed = Disco { $disc }: velocidade definida como { $velocity }
aim-across-the-line = Aqui os discos se movem sobre uma reta: { $keys } apontam ao longo dela
key-left-right = Esquerda e Direita
key-up-down = Cima e Baixo
dropped-file = arquivo solto
dropped-not-text = { $name }: não é um arquivo de texto
dropped-unreadable = { $name }: { $error }
dropped-empty = um arquivo solto sem conteúdo
link-cannot-open = A cena deste link não pode ser aberta: { $error }
origin-default = cena padrão embutida
origin-shared-link = o link compartilhado
