/**
 * The NAO link's values: NAOqi's ALValue wire form to plain Java and back ({@code MixedValueCodec}), a typed call
 * parameter as a user types it ({@code ParamSyntax}), camera resolution ids ({@code CameraFormat}), a JPEG
 * frame's size ({@code JpegHeader}) and the modules the robot side answers ({@code NaoModules}).
 * <p>
 * May depend on: the protocol layer only; pure.
 */
package touchline.protocol.nao;
