// Resolves: (docs/page.md, "Section") and (README, "Present").
// Dangles: (docs/missing.md), (docs/page.md, "No such section") and (README, "Writing
// effects").
