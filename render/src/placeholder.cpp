namespace lancer {}
