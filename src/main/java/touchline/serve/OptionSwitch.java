package touchline.serve;

import touchline.transport.SendResult;

/**
 * What a serving console lets a tool on its own machine ask of it: switch one robot's debug
 * option on or off ({@code touchline options --connect}). The console takes it through its own
 * match mode, as its window's options view would: a switch during play is held there.
 */
@FunctionalInterface
public interface OptionSwitch {

    /** {@code on}: switch {@code option} of robot {@code robotId} on; otherwise off, whoever switched it on. */
    SendResult switchOption(int robotId, String option, boolean on);
}
