/**
 * The Humanoid Soccer League 2026 referee, as the official GameController 7.0.0 / 6.0.1 keeps it: {@code HslGame}
 * (a {@code game.LeagueGame}: the one engine with the {@code HslLeague} strategy) over {@code HslState} ({@code HslTeam}, {@code HslPlayer}, {@code HslPhase}, {@code HslPlayState}), changed by
 * {@code HslAction}s ({@code FreeSetPlay}, {@code HslPenalize}, {@code HslUnpenalize}, {@code StopPlay}, {@code
 * TeamMessage}, ...) and the actions every league shares ({@code game.Goal}, {@code game.StartPenaltyShootout}), with each release's rules ({@code HslRules}) and competitions ({@code Competition}), and the
 * text form of its actions ({@code HslActionSyntax}).
 * <p>
 * May depend on: game and protocol; pure.
 */
package touchline.game.hsl;
