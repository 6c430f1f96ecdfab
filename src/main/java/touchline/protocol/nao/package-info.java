/**
 * The NAO link's values: NAOqi's ALValue wire form to plain Java and back ({@code MixedValueCodec}), a typed call
 * parameter as a user types it ({@code ParamSyntax}), camera resolution ids ({@code CameraFormat}) and a JPEG
 * frame's size ({@code JpegHeader}).
 * <p>
 * May depend on: the protocol layer only; pure.
 */
package touchline.protocol.nao;
