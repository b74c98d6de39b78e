<?xml version="1.0"?>
<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0" xmlns:gml="http://www.opengis.net/gml" xmlns:bldg="http://www.opengis.net/citygml/building/2.0" xmlns:app="http://www.opengis.net/citygml/appearance/2.0" xmlns:xlink="http://www.w3.org/1999/xlink" xmlns:dem="http://www.opengis.net/citygml/relief/2.0">
<gml:boundedBy><gml:Envelope srsName="urn:ogc:def:crs,crs:EPSG::28992,crs:EPSG::5709" srsDimension="3"/></gml:boundedBy>
<core:cityObjectMember><bldg:Building gml:id="b"><bldg:lod2Solid><gml:Solid><gml:exterior><gml:CompositeSurface><gml:surfaceMember xlink:href="#roof"/></gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod2Solid>
<bldg:boundedBy><bldg:RoofSurface><bldg:lod2MultiSurface><gml:MultiSurface><gml:surfaceMember><gml:Polygon gml:id="roof">
<gml:exterior><gml:LinearRing><gml:posList>0 0 6 10 0 6 10 8 6 0 8 6 0 0 6</gml:posList></gml:LinearRing></gml:exterior>
<gml:interior><gml:LinearRing><gml:pos>4 2 6</gml:pos><gml:pos>4 5 6</gml:pos><gml:pos>6 5 6</gml:pos><gml:pos>4 2 6</gml:pos></gml:LinearRing></gml:interior>
</gml:Polygon></gml:surfaceMember></gml:MultiSurface></bldg:lod2MultiSurface></bldg:RoofSurface></bldg:boundedBy>
<bldg:consistsOfBuildingPart><bldg:BuildingPart><bldg:lod1MultiSurface><gml:MultiSurface><gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:coordinates>0,0,0 1,0,0 1,1,0</gml:coordinates></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember></gml:MultiSurface></bldg:lod1MultiSurface></bldg:BuildingPart></bldg:consistsOfBuildingPart>
</bldg:Building></core:cityObjectMember>
<app:appearanceMember><app:Appearance><app:surfaceDataMember><app:X3DMaterial gml:id="m"><app:target>#roof</app:target></app:X3DMaterial></app:surfaceDataMember>
<app:surfaceDataMember><app:ParameterizedTexture><app:imageURI>t.jpg</app:imageURI><app:target uri="#roof"/></app:ParameterizedTexture></app:surfaceDataMember></app:Appearance></app:appearanceMember>
</core:CityModel>
